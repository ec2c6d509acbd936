// Child processes for the tests that run cosph-coupler and cosph-dummy
// together: started with posix_spawn, stdout and stderr sent to files, waited
// for with a deadline, and killed (SIGKILL) and reaped by the destructor if
// still running, so that a failing test can neither hang ctest nor leave
// processes behind.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "test_support.hpp"

extern char** environ;

namespace cosph::testing {

using Clock = std::chrono::steady_clock;

class ChildProcess {
 public:
  static constexpr int kStillRunning = -1;

  // Runs argv[0] with stdout to LOG.out and stderr to LOG.err.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log)
      : out_path_(log + ".out"), err_path_(log + ".err") {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    const int error = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error(argv[0] + ": cannot start: " + std::strerror(error));
  }
  ~ChildProcess() { kill_and_reap(); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The exit code (128 + signal if killed by one), or kStillRunning when the
  // deadline passes first.
  int wait_until(Clock::time_point deadline) {
    while (!reaped_) {
      int status = 0;
      const pid_t done = ::waitpid(pid_, &status, WNOHANG);
      if (done == pid_) {
        reaped_ = true;
        code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      } else if (Clock::now() >= deadline) {
        return kStillRunning;
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    }
    return code_;
  }

  void kill_and_reap() {
    if (reaped_) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    reaped_ = true;
    code_ = 128 + SIGKILL;
  }

  void signal(int signal_number) {
    if (!reaped_) ::kill(pid_, signal_number);
  }

  // Whether a process with this pid still exists (after reaping: it must not).
  bool exists() const { return ::kill(pid_, 0) == 0 || errno != ESRCH; }
  bool reaped() const { return reaped_; }
  std::string err() const { return read_text(err_path_); }
  std::string out() const { return read_text(out_path_); }

 private:
  std::string out_path_, err_path_;
  pid_t pid_ = -1;
  bool reaped_ = false;
  int code_ = kStillRunning;
};

}  // namespace cosph::testing
