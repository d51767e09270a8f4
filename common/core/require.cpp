#include "common/core/require.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "common/core/error.hpp"

namespace mpfd {

void require(bool ok, std::string_view where, std::string_view what, double value,
             std::string_view rule) {
  if (ok && std::isfinite(value)) return;
  std::string message(where);
  message.append(": ").append(what).append(" must be ").append(rule);
  message.append(", got ").append(shortest_text(value));
  throw Error(message);
}

std::string shortest_text(double x) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  return {buffer.data(), result.ptr};
}

std::string number_text(double x, int significant) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", significant, x);
  return text;
}

}  // namespace mpfd
