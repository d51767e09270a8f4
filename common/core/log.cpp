#include "common/core/log.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <mutex>

namespace mpfd {
namespace {

LogLevel parse_level(const char* text) {
  if (text == nullptr) return LogLevel::info;
  const std::string_view s(text);
  if (s == "debug") return LogLevel::debug;
  if (s == "warn") return LogLevel::warn;
  if (s == "error") return LogLevel::error;
  return LogLevel::info;
}

constexpr const char* kLevelName[] = {"debug", "info", "warn", "error"};

/// UTC time as 2026-11-24T08:00:00.123Z.
std::string utc_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900,
                utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec,
                static_cast<int>(millis));
  return text;
}

}  // namespace

LogLevel log_threshold() {
  static const LogLevel threshold = parse_level(std::getenv("MPFD_LOG_LEVEL"));
  return threshold;
}

void Logger::emit(LogLevel level, std::string_view text) const {
  static std::mutex mutex;
  std::string line = utc_timestamp();
  line.append(" [").append(kLevelName[static_cast<int>(level)]).append("] ");
  line.append(module_).append(": ").append(text).append("\n");
  const std::lock_guard lock(mutex);
  std::cerr << line << std::flush;
}

}  // namespace mpfd
