#pragma once
// The one message format of every input check in MPFD:
//   "<where>: <what> must be <rule>, got <value>"
// e.g. "ideal_gas: gamma must be > 1, got 0.9" (docs/STYLE: name the key, the
// value and the rule).

#include <string>
#include <string_view>

namespace mpfd {

/// Throws mpfd::Error with the message above unless `ok` holds and `value` is
/// finite (so NaN and inf always fail).
void require(bool ok, std::string_view where, std::string_view what, double value,
             std::string_view rule);

/// Shortest decimal form that reads back to x exactly: "0.9", "3.712e+11", "nan".
[[nodiscard]] std::string shortest_text(double x);

/// x with `significant` digits (printf %g): number_text(0.1 + 0.2, 4) is "0.3".
[[nodiscard]] std::string number_text(double x, int significant);

}  // namespace mpfd
