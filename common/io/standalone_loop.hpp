#pragma once
// The step loop every standalone run shares (fdm_solver run, mpm_solver run):
// gauges at their interval (or every step), snapshots landing exactly on the
// output times, a progress line, the max_steps guard, and a summary.json that
// survives any failure (status "failed" with the first error, never hidden by
// a second one). What a snapshot, a gauge sample or a summary holds is the
// program's business, given as callbacks.

#include <algorithm>
#include <chrono>
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <string_view>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "common/core/progress.hpp"

namespace mpfd::io {

struct StandaloneCallbacks {
  bool has_gauges = false;
  std::function<void()> record_gauges;  ///< one sample of every gauge now
  std::function<void()> write_output;   ///< a snapshot (and whatever goes with it)
  std::function<void()> flush_gauges;   ///< gauge samples to disk
  std::function<void(const std::string& status, const std::string& error)> write_summary;
};

/// Peak resident memory of this process so far [bytes].
[[nodiscard]] long long peak_memory_bytes();

/// Runs `solver` (time(), steps(), step_toward(target), advance(dt)) to the
/// scene's end time; `solver_seconds` accumulates the time spent in advance()
/// (the callbacks may read it). Rethrows whatever stopped the run after
/// writing the "failed" summary. `program` names the program in messages,
/// `progress_label` leads its progress line.
template <class Solver>
void run_standalone_loop(Solver& solver, const config::Scene& scene, std::string_view program,
                         std::string_view progress_label, const StandaloneCallbacks& io,
                         double& solver_seconds) {
  using Clock = std::chrono::steady_clock;
  try {
    ProgressLine progress(std::cerr, scene.time.end, std::string(progress_label));
    const double end = scene.time.end;
    double next_output = 0.0;
    double next_gauge = 0.0;
    while (true) {
      if (io.has_gauges && (!scene.output.gauge_interval || solver.time() >= next_gauge)) {
        io.record_gauges();
        if (scene.output.gauge_interval)
          while (next_gauge <= solver.time()) next_gauge += *scene.output.gauge_interval;
      }
      if (solver.time() >= next_output || solver.time() >= end) {
        io.write_output();
        while (next_output <= solver.time()) next_output += scene.output.interval;
      }
      if (solver.time() >= end) break;
      if (solver.steps() >= scene.time.max_steps)
        throw Error(std::string(program) +
                    ": reached time.max_steps = " + std::to_string(scene.time.max_steps) +
                    " at t = " + std::to_string(solver.time()) + " s of " + std::to_string(end) +
                    " s; raise time.max_steps or coarsen the grid");
      const double dt = solver.step_toward(std::min(next_output, end));  // land on output times
      const auto step_start = Clock::now();
      solver.advance(dt);
      solver_seconds += std::chrono::duration<double>(Clock::now() - step_start).count();
      progress.update(solver.steps(), solver.time());
    }
    progress.finish(solver.steps(), solver.time());
    io.write_summary("completed", "");
  } catch (const std::exception& e) {
    // Keep what was recorded, but never let a second failure hide the first.
    try {
      io.flush_gauges();
      io.write_summary("failed", e.what());
    } catch (const std::exception&) {
    }
    throw;
  }
}

}  // namespace mpfd::io
