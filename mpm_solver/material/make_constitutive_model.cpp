#include <string>
#include <type_traits>
#include <variant>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/material/elastic_model.hpp"
#include "mpm_solver/material/fluid_model.hpp"
#include "mpm_solver/material/johnson_cook_model.hpp"

namespace mpfd::mpm {
namespace {

template <class Strength>
constexpr std::string_view strength_name() {
  if constexpr (std::is_same_v<Strength, config::ElasticStrength>) return "elastic";
  if constexpr (std::is_same_v<Strength, config::JohnsonCook>) return "johnson_cook";
  return "none";
}

/// A strength model needs a condensed-matter EOS: a gas or detonation products
/// cannot carry shear, and an explosive is burnt as a fluid (T (3-1)).
template <class Strength>
void require_solid(const config::Material& material) {
  const std::string prefix = "material '" + material.name + "': strength '" +
                             std::string(strength_name<Strength>()) + "' ";
  if (std::holds_alternative<eos::IdealGas>(material.eos) ||
      std::holds_alternative<eos::Jwl>(material.eos)) {
    throw Error(prefix + "needs a solid equation of state (mie_gruneisen or polynomial), got '" +
                std::string(eos::name(material.eos)) + "'");
  }
  if (material.explosive) {
    throw Error(prefix +
                "cannot apply to an explosive (it detonates and is burnt as a fluid); "
                "expected strength 'none'");
  }
}

}  // namespace

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const config::Material& material) {
  return std::visit(
      [&](const auto& strength) -> std::unique_ptr<ConstitutiveModel> {
        using Strength = std::decay_t<decltype(strength)>;
        if constexpr (std::is_same_v<Strength, config::NoStrength>) {
          return std::make_unique<FluidModel>(material.eos);
        } else {
          require_solid<Strength>(material);
          if constexpr (std::is_same_v<Strength, config::ElasticStrength>) {
            return std::make_unique<ElasticModel>(material.eos, strength.shear_modulus);
          } else {
            static_assert(std::is_same_v<Strength, config::JohnsonCook>,
                          "a new strength model needs its line here");
            return std::make_unique<JohnsonCookModel>(material.eos, strength);
          }
        }
      },
      material.strength);
}

}  // namespace mpfd::mpm
