#pragma once
// The elastic shear modulus G a scene's strength section gives (0 for fluids):
// the shear-wave speed of the non-reflecting face and the contact normal's
// stiffness ranking read it.

#include <variant>

#include "common/config/scene.hpp"

namespace mpfd::mpm {

[[nodiscard]] inline double shear_modulus(const config::AnyStrength& strength) {
  if (const auto* e = std::get_if<config::ElasticStrength>(&strength)) return e->shear_modulus;
  if (const auto* j = std::get_if<config::JohnsonCook>(&strength)) return j->shear_modulus;
  return 0.0;
}

}  // namespace mpfd::mpm
