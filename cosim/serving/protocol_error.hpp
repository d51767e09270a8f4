#pragma once
// A request a solver cannot carry out, with the protocol's error code
// (proto/README.md §9). The serve loop answers it as Error{code, message, fatal}
// and, when fatal, stops with it.

#include <string>

#include "common/core/error.hpp"
#include "cosim/message.hpp"

namespace mpfd::cosim {

class ProtocolError : public Error {
 public:
  ProtocolError(cosim::v1::ErrorCode code, const std::string& message, bool fatal = true)
      : Error(message), code_(code), fatal_(fatal) {}

  [[nodiscard]] cosim::v1::ErrorCode code() const { return code_; }
  [[nodiscard]] bool fatal() const { return fatal_; }

 private:
  cosim::v1::ErrorCode code_;
  bool fatal_;
};

}  // namespace mpfd::cosim
