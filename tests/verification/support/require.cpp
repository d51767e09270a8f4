#include "tests/verification/support/require.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include "common/core/error.hpp"

namespace mpfd::verification {

void require(bool ok, std::string_view where, std::string_view what, double value,
             std::string_view rule) {
  if (ok && std::isfinite(value)) return;
  std::string message(where);
  message.append(": ").append(what).append(" must be ").append(rule);
  message.append(", got ").append(format_number(value));
  throw Error(message);
}

std::string format_number(double x) {
  std::array<char, 32> digits{};
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), x).ptr;
  return {digits.data(), end};
}

}  // namespace mpfd::verification
