#include "coupler/run/solver_handle.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>

#include "common/core/error.hpp"

extern char** environ;

namespace mpfd::coupler {
namespace {

using Clock = std::chrono::steady_clock;

class ThreadSolver final : public SolverHandle {
 public:
  ThreadSolver(std::string name, ServeFunction serve, zmq::context_t& context, std::string endpoint)
      : SolverHandle(std::move(name)) {
    thread_ = std::thread([this, serve, &context, endpoint = std::move(endpoint)] {
      std::string how = "returned";
      try {
        serve(context, endpoint, this->name());
      } catch (const std::exception& error) {
        how = std::string("stopped with an error: ") + error.what();
      }
      const std::lock_guard lock(mutex_);
      how_ = how;
      done_ = true;
    });
  }
  ~ThreadSolver() override {
    if (thread_.joinable()) thread_.join();
  }

  std::optional<std::string> ended() override {
    const std::lock_guard lock(mutex_);
    if (!done_) return std::nullopt;
    return how_;
  }

  std::string finish(std::chrono::milliseconds grace) override {
    const auto deadline = Clock::now() + grace;
    while (!ended() && Clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    // A thread cannot be killed: it ends by itself at its idle timeout.
    if (!ended()) return "still running (it stops at its idle timeout)";
    thread_.join();
    return *ended();
  }

 private:
  std::thread thread_;
  std::mutex mutex_;
  bool done_ = false;
  std::string how_;
};

class ChildSolver final : public SolverHandle {
 public:
  ChildSolver(std::string name, std::vector<std::string> argv, const std::string& log_file)
      : SolverHandle(std::move(name)), log_file_(log_file) {
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int failed = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (failed != 0)
      throw Error("cannot start solver '" + this->name() + "' (" + argv[0] +
                  "): " + std::strerror(failed));
  }
  ~ChildSolver() override { finish(std::chrono::milliseconds(0)); }
  std::optional<int> process_id() const override { return pid_; }

  std::optional<std::string> ended() override {
    if (how_) return how_;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return std::nullopt;
    std::string how = WIFEXITED(status)
                          ? "exited with code " + std::to_string(WEXITSTATUS(status))
                          : "was killed by signal " + std::to_string(WTERMSIG(status));
    how_ = "(pid " + std::to_string(pid_) + ") " + how + last_log_line();
    return how_;
  }

  std::string finish(std::chrono::milliseconds grace) override {
    const auto deadline = Clock::now() + grace;
    while (!ended() && Clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!ended()) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      how_ = "(pid " + std::to_string(pid_) + ") did not stop and was killed";
    }
    return *how_;
  }

 private:
  std::string last_log_line() const {
    std::ifstream in(log_file_);
    std::string line, last;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    return last.empty() ? "" : "; its last log line: " + last;
  }

  pid_t pid_ = 0;
  std::string log_file_;
  std::optional<std::string> how_;
};

class ExternalSolver final : public SolverHandle {
 public:
  using SolverHandle::SolverHandle;
  std::optional<std::string> ended() override { return std::nullopt; }
  std::string finish(std::chrono::milliseconds) override { return "external"; }
};

}  // namespace

std::unique_ptr<SolverHandle> start_thread(std::string name, ServeFunction serve,
                                           zmq::context_t& context, std::string endpoint) {
  return std::make_unique<ThreadSolver>(std::move(name), serve, context, std::move(endpoint));
}

std::unique_ptr<SolverHandle> start_process(std::string name, std::vector<std::string> argv,
                                            const std::string& log_file) {
  return std::make_unique<ChildSolver>(std::move(name), std::move(argv), log_file);
}

std::unique_ptr<SolverHandle> external_solver(std::string name) {
  return std::make_unique<ExternalSolver>(std::move(name));
}

}  // namespace mpfd::coupler
