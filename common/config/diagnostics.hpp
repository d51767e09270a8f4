#pragma once
// Internal: collects the problems of one scene file so that all of them are
// reported together, and remembers where each key path sits in the file so
// that checks made after parsing (scene_checks.cpp) can still point at a line.

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/config/scene_error.hpp"

namespace mpfd::config {

struct Mark {
  int line = 0;    ///< 1-based; 0 = unknown
  int column = 0;  ///< 1-based
};

class Diagnostics {
 public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}

  void remember(const std::string& path, Mark mark) { marks_.emplace(path, mark); }
  /// Where `path` (or, if it was never seen, its nearest remembered parent) is.
  Mark locate(std::string_view path) const;

  void error(Mark mark, std::string path, std::string message);
  /// An error at the remembered place of `path`.
  void error(const std::string& path, std::string message) {
    error(locate(path), path, std::move(message));
  }

  /// False if an error was reported at `path` or below it.
  bool clean(std::string_view path) const;
  /// Throws SceneError with every problem, in file order, if there is any.
  void throw_if_any() const;

 private:
  std::string file_;
  std::map<std::string, Mark, std::less<>> marks_;
  std::vector<Diagnostic> errors_;
};

/// "; did you mean 'gamma'?" if one of `allowed` is a likely typo (small edit
/// distance) or completion of `got`, else "".
std::string did_you_mean(std::string_view got, const std::vector<std::string>& allowed);

/// "a, b, c".
std::string join(const std::vector<std::string>& items, std::string_view separator = ", ");

}  // namespace mpfd::config
