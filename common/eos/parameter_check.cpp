#include "common/eos/parameter_check.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include "common/core/error.hpp"

namespace mpfd::eos {

void require_parameter(bool ok, std::string_view model, std::string_view parameter, double value,
                       std::string_view rule) {
  if (ok && std::isfinite(value)) return;
  std::string message(model);
  message.append(": ").append(parameter).append(" must be ").append(rule);
  message.append(", got ").append(format_parameter(value));
  throw Error(message);
}

std::string format_parameter(double x) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  return {buffer.data(), result.ptr};
}

}  // namespace mpfd::eos
