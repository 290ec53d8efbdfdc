#pragma once
// Starts the bpmkit executable (BPMKIT_EXE) as a child process that a test can signal: fork and
// exec, its output into a log file. bpmkit_process.hpp's popen cannot deliver a SIGKILL to bpmkit
// itself (it would hit the shell).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace bpm::test {

class BpmkitChild {
 public:
  /// Runs `bpmkit ARGS...` in `cwd`, stdout and stderr into `log`.
  BpmkitChild(const std::vector<std::string>& args, const std::string& cwd,
              const std::string& log) {
    std::vector<std::string> argv{BPMKIT_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> raw;
    for (std::string& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
      // Only async-signal-safe calls between fork and exec.
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(127);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::execv(raw[0], raw.data());
      ::_exit(127);
    }
    if (pid_ < 0) ADD_FAILURE() << "fork failed";
  }
  ~BpmkitChild() {
    if (pid_ > 0 && !reaped_) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  BpmkitChild(const BpmkitChild&) = delete;
  BpmkitChild& operator=(const BpmkitChild&) = delete;

  /// Polls `ready` every 2 ms until it holds (true) or the child has exited or `timeout` passed
  /// (false).
  bool wait_until(const std::function<bool()>& ready,
                  std::chrono::seconds timeout = std::chrono::seconds(120)) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      if (ready()) return true;
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        reaped_ = true;
        status_ = status;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }
  bool running() const { return !reaped_; }
  void signal(int sig) const { ::kill(pid_, sig); }
  /// Waits for the child; returns its wait status.
  int wait() {
    if (!reaped_) {
      ::waitpid(pid_, &status_, 0);
      reaped_ = true;
    }
    return status_;
  }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

}  // namespace bpm::test
