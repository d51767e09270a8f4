#pragma once
// One logger per module ("fdm.scheme", "coupler.handshake"): each line carries
// the UTC time, the severity and the module. The threshold comes from the
// environment variable MPFD_LOG_LEVEL (debug|info|warn|error, default info);
// debug lines are compiled out of release builds.

#include <sstream>
#include <string>
#include <string_view>

namespace mpfd {

enum class LogLevel { debug = 0, info = 1, warn = 2, error = 3 };

/// The threshold read once from MPFD_LOG_LEVEL.
LogLevel log_threshold();

class Logger {
 public:
  explicit Logger(std::string module) : module_(std::move(module)) {}

  template <typename... Args>
  void debug([[maybe_unused]] const Args&... args) const {
#ifndef NDEBUG
    write(LogLevel::debug, args...);
#endif
  }
  template <typename... Args>
  void info(const Args&... args) const {
    write(LogLevel::info, args...);
  }
  template <typename... Args>
  void warn(const Args&... args) const {
    write(LogLevel::warn, args...);
  }
  template <typename... Args>
  void error(const Args&... args) const {
    write(LogLevel::error, args...);
  }

 private:
  template <typename... Args>
  void write(LogLevel level, const Args&... args) const {
    if (level < log_threshold()) return;
    std::ostringstream text;
    (text << ... << args);
    emit(level, text.str());
  }
  void emit(LogLevel level, std::string_view text) const;

  std::string module_;
};

}  // namespace mpfd
