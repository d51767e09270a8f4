#pragma once
// A program started by a test: its stderr goes to a file, it is waited for
// with a timeout, and killed (by its pid) if the test ends while it runs.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/core/error.hpp"

extern char** environ;

namespace mpfd::testing {

class ChildProcess {
 public:
  ChildProcess(std::vector<std::string> argv, std::filesystem::path stderr_file)
      : stderr_file_(std::move(stderr_file)) {
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_file_.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int failed = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (failed != 0) throw Error("cannot start " + argv[0] + ": error " + std::to_string(failed));
  }
  ~ChildProcess() {
    if (running_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// The exit code once the program has exited within `timeout`; nothing if it still runs.
  std::optional<int> wait_for(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (running_) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        running_ = false;
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      } else if (std::chrono::steady_clock::now() >= deadline) {
        return std::nullopt;
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds{10});
      }
    }
    return exit_code_;
  }

  /// What the program has written to stderr so far.
  std::string error_output() const {
    std::ifstream in(stderr_file_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  std::filesystem::path stderr_file_;
  pid_t pid_ = -1;
  bool running_ = true;
  int exit_code_ = -1;
};

/// `program serve` on `endpoint` (one thread, the given idle timeout), its log in
/// a temporary file named after the program, `tag` and this process.
inline std::unique_ptr<ChildProcess> start_serve(const std::string& program,
                                                 const std::string& endpoint,
                                                 const std::string& idle_seconds,
                                                 const std::string& tag) {
  const auto log = std::filesystem::temp_directory_path() /
                   ("mpfd-" + std::filesystem::path(program).filename().string() + "-serve-" + tag +
                    "-" + std::to_string(::getpid()) + ".log");
  return std::make_unique<ChildProcess>(
      std::vector<std::string>{program, "serve", "--endpoint", endpoint, "--idle-timeout",
                               idle_seconds, "--threads", "1"},
      log);
}

}  // namespace mpfd::testing
