#include <string>
#include <type_traits>
#include <variant>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/material/fluid_model.hpp"

namespace mpfd::mpm {

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const config::Material& material) {
  return std::visit(
      [&](const auto& strength) -> std::unique_ptr<ConstitutiveModel> {
        using Strength = std::decay_t<decltype(strength)>;
        if constexpr (std::is_same_v<Strength, config::NoStrength>) {
          return std::make_unique<FluidModel>(material.eos);
        } else {
          throw Error("material '" + material.name +
                      "': strength models are not built into mpm_solver yet");
        }
      },
      material.strength);
}

}  // namespace mpfd::mpm
