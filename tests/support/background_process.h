#pragma once
/// A program a test starts and talks to while it runs (the watch server), with its standard
/// output and error in a log file.

#include <chrono>
#include <csignal>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "support/scratch_files.h"
#include "support/spawn.h"

namespace mjray::test {

/// Runs from construction; killed (SIGKILL) and reaped on destruction if still running.
class BackgroundProcess {
 public:
  /// Starts argv[0] with `argv`, its stdout and stderr appended to `log`.
  BackgroundProcess(const std::vector<std::string>& argv, const std::filesystem::path& log)
      : log_(log), pid_(spawn(argv, [path = log.c_str()] { log_output_to(path); })) {}
  ~BackgroundProcess() {
    if (running()) kill_and_reap(pid_);
  }
  BackgroundProcess(const BackgroundProcess&) = delete;
  BackgroundProcess& operator=(const BackgroundProcess&) = delete;

  bool running() const { return pid_ > 0 && !exit_code_; }
  void signal(int sig) const { ::kill(pid_, sig); }

  /// The exit code (128 + N when signal N ended it) within `timeout`, else nothing.
  std::optional<int> wait(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!exit_code_ && pid_ > 0) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_)
        exit_code_ = exit_code_of(status);
      else if (std::chrono::steady_clock::now() > end) break;
      else std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return exit_code_;
  }

  /// Everything it printed so far.
  std::string log() const { return read_file(log_); }

  /// The first match of `pattern`'s group 1 in the log within `timeout` ("" if none, or if
  /// the program ended first).
  std::string wait_for_log(const std::regex& pattern, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      std::smatch m;
      const std::string text = log();
      if (std::regex_search(text, m, pattern)) return m[1].str();
      if (wait(std::chrono::milliseconds(0))) return "";
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return "";
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
};

}  // namespace mjray::test
