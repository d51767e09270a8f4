#pragma once
// The one message format of every EOS validate():
//   "<model>: <parameter> must be <rule>, got <value>"

#include <string>
#include <string_view>

namespace mpfd::eos {

/// Throws mpfd::Error with the message above unless `ok` holds and `value` is
/// finite (so NaN and inf always fail).
void require_parameter(bool ok, std::string_view model, std::string_view parameter, double value,
                       std::string_view rule);

/// Shortest decimal form that reads back to x: "0.9", "3.712e+11", "nan".
[[nodiscard]] std::string format_parameter(double x);

}  // namespace mpfd::eos
