#pragma once
// The one message format of every input check in this library (as in
// common/eos): "<where>: <what> must be <rule>, got <value>".

#include <string>
#include <string_view>

namespace mpfd::verification {

/// Throws mpfd::Error with the message above unless `ok` holds and `value` is
/// finite (so NaN and inf always fail).
void require(bool ok, std::string_view where, std::string_view what, double value,
             std::string_view rule);

/// Shortest decimal form that reads back to x: "0.9", "1e-12", "nan".
[[nodiscard]] std::string format_number(double x);

}  // namespace mpfd::verification
