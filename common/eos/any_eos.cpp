#include "common/eos/any_eos.hpp"

namespace mpfd::eos {

double pressure(const AnyEos& eos, double rho, double e) {
  return std::visit([=](const auto& model) { return model.pressure(rho, e); }, eos);
}

double sound_speed(const AnyEos& eos, double rho, double e) {
  return std::visit([=](const auto& model) { return model.sound_speed(rho, e); }, eos);
}

double internal_energy(const AnyEos& eos, double rho, double p) {
  return std::visit([=](const auto& model) { return model.internal_energy(rho, p); }, eos);
}

std::string_view name(const AnyEos& eos) {
  return std::visit([](const auto& model) { return model.name(); }, eos);
}

void validate(const AnyEos& eos) {
  std::visit([](const auto& model) { validate(model); }, eos);
}

}  // namespace mpfd::eos
