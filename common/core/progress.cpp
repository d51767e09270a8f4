#include "common/core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace mpfd {
namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(250);

bool is_terminal(const std::ostream& out) {
  if (&out == &std::cerr) return isatty(STDERR_FILENO) != 0;
  if (&out == &std::cout) return isatty(STDOUT_FILENO) != 0;
  return false;
}

std::string clock_text(double seconds) {
  const auto s = static_cast<long>(std::max(0.0, seconds) + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

}  // namespace

ProgressLine::ProgressLine(std::ostream& out, double end_time, std::string label)
    : ProgressLine(out, end_time, std::move(label), is_terminal(out)) {}

ProgressLine::ProgressLine(std::ostream& out, double end_time, std::string label,
                           bool force_enabled)
    : out_(out), end_time_(end_time), label_(std::move(label)), enabled_(force_enabled) {}

ProgressLine::~ProgressLine() {
  if (enabled_ && drawn_) out_ << '\n' << std::flush;
}

std::string ProgressLine::format(std::int64_t step, double time, double wall_seconds) const {
  const double fraction = end_time_ > 0 ? std::clamp(time / end_time_, 0.0, 1.0) : 0.0;
  const std::string eta =
      fraction > 0 ? clock_text(wall_seconds * (1.0 - fraction) / fraction) : "--:--:--";
  char text[160];
  std::snprintf(text, sizeof text, "%s step %lld  t = %.4e s  %5.1f %%  wall %s  ETA %s",
                label_.c_str(), static_cast<long long>(step), time, 100.0 * fraction,
                clock_text(wall_seconds).c_str(), eta.c_str());
  return text;
}

void ProgressLine::update(std::int64_t step, double time) {
  if (!enabled_) return;
  const auto now = Clock::now();
  if (drawn_ && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  drawn_ = true;
  const double wall = std::chrono::duration<double>(now - start_).count();
  out_ << '\r' << format(step, time, wall) << "\x1b[K" << std::flush;
}

void ProgressLine::finish(std::int64_t step, double time) {
  if (!enabled_) return;
  drawn_ = false;
  last_draw_ = {};
  const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
  out_ << '\r' << format(step, time, wall) << "\x1b[K\n" << std::flush;
}

}  // namespace mpfd
