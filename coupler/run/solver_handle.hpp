#pragma once
// A solver the coupler talks to: a thread of this process (embedded), a child
// process, or an external program it only knows by name. The coupler asks a
// handle whether its solver has died (to name it in an error) and stops the
// ones it started.

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

namespace mpfd::coupler {

class SolverHandle {
 public:
  explicit SolverHandle(std::string name) : name_(std::move(name)) {}
  virtual ~SolverHandle() = default;
  SolverHandle(const SolverHandle&) = delete;
  SolverHandle& operator=(const SolverHandle&) = delete;

  [[nodiscard]] const std::string& name() const { return name_; }
  /// How the solver ended if it has ended ("exited with code 1: ..."), else nothing.
  [[nodiscard]] virtual std::optional<std::string> ended() = 0;
  /// Waits up to `grace` for the solver to end by itself, then ends it (a
  /// child: SIGKILL by its pid). Returns how it ended.
  virtual std::string finish(std::chrono::milliseconds grace) = 0;
  /// The process id of a solver the coupler started as a child, else nothing.
  [[nodiscard]] virtual std::optional<int> process_id() const { return std::nullopt; }

 private:
  std::string name_;
};

/// A solver entry point run on a thread: serve(context, endpoint, name).
using ServeFunction = void (*)(zmq::context_t&, const std::string&, const std::string&);

/// Runs `serve` on a thread; an exception it throws is kept as the way it ended.
[[nodiscard]] std::unique_ptr<SolverHandle> start_thread(std::string name, ServeFunction serve,
                                                         zmq::context_t& context,
                                                         std::string endpoint);

/// Starts `argv` as a child process (stderr to `log_file`).
[[nodiscard]] std::unique_ptr<SolverHandle> start_process(std::string name,
                                                          std::vector<std::string> argv,
                                                          const std::string& log_file);

/// A solver started by someone else: never reports an end, finish() does nothing.
[[nodiscard]] std::unique_ptr<SolverHandle> external_solver(std::string name);

}  // namespace mpfd::coupler
