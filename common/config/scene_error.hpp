#pragma once
// The user-facing error of a scene file: every problem found in it, each with
// file, line, column, key path and what was expected. what() lists them one
// per line, e.g.
//   scene.yaml:12:5: materials.air.eos.gamma: expected a number > 1, got 0.9

#include <string>
#include <vector>

#include "common/core/error.hpp"

namespace mpfd::config {

struct Diagnostic {
  std::string file;
  int line = 0;    ///< 1-based; 0 when the problem has no place in the file
  int column = 0;  ///< 1-based
  std::string
      path;  ///< key path such as `materials.air.eos.gamma` or `bodies[0].shape`; may be empty
  std::string message;
};

/// `file:line:column: path: message` (parts that are unknown are left out).
std::string to_string(const Diagnostic& diagnostic);

class SceneError : public Error {
 public:
  explicit SceneError(std::vector<Diagnostic> diagnostics);

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace mpfd::config
