#pragma once
// A one-line progress report for long runs: step, simulated time, percent of
// the end time, wall time and ETA, redrawn in place at most a few times per
// second. Silent when the stream is not a terminal (logs and CI stay clean).

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace mpfd {

class ProgressLine {
 public:
  /// Enabled only if `out` is std::cerr/std::cout attached to a terminal,
  /// unless `force` says otherwise (tests).
  ProgressLine(std::ostream& out, double end_time, std::string label);
  ProgressLine(std::ostream& out, double end_time, std::string label, bool force_enabled);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Redraws the line if enough wall time has passed since the last redraw.
  void update(std::int64_t step, double time);
  /// Draws the final state and ends the line.
  void finish(std::int64_t step, double time);
  [[nodiscard]] bool enabled() const { return enabled_; }

  /// The text of the line for a given state (exposed for tests).
  [[nodiscard]] std::string format(std::int64_t step, double time, double wall_seconds) const;

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& out_;
  double end_time_;
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_{};
};

}  // namespace mpfd
