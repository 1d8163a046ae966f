#pragma once
/// A program run in the background, its stderr read line by line: for tests that interrupt
/// a render or act on what it has printed.

#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include <sys/types.h>

namespace mjray::test {

/// Runs argv[0] with the arguments that follow; stderr is a pipe the test reads.
class ChildProcess {
 public:
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Reads stderr until a line contains `text`; false at the end of the output.
  bool wait_for(const std::string& text);
  /// Sends `signal` to the process.
  void interrupt(int signal = SIGINT);
  /// Reads the rest of stderr, waits for the exit and returns its code (128 + N when signal
  /// N ended it).
  int exit_code();
  pid_t pid() const { return pid_; }
  /// What stderr has said so far.
  const std::string& log() const { return log_; }

 private:
  pid_t pid_ = -1;
  FILE* err_ = nullptr;
  std::string log_;
  bool reaped_ = false;
  int code_ = -1;
};

}  // namespace mjray::test
