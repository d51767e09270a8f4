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

/// A Restore that failed after the solver's state was replaced: the zone holds
/// neither its Setup's state nor the checkpoint's, so the error is fatal and
/// `program` stops rather than serve a mixture.
[[nodiscard]] inline ProtocolError half_restored(const std::string& program,
                                                 const std::string& file, const std::string& what) {
  return {cosim::v1::ERROR_CODE_IO,
          "Restore from '" + file + "' failed after the state was replaced: " + what +
              "; the zone is neither its Setup's nor the checkpoint's, so " + program + " stops",
          true};
}

}  // namespace mpfd::cosim
