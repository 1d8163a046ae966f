#include "support/child_process.h"

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

#include "support/spawn.h"

namespace mjray::test {

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  int fds[2];
  if (pipe(fds) != 0) return;
  pid_ = spawn(argv, [&] {
    dup2(fds[1], 2);
    close(fds[0]);
    close(fds[1]);
  });
  close(fds[1]);
  err_ = fdopen(fds[0], "r");
}

ChildProcess::~ChildProcess() {
  if (!reaped_) kill_and_reap(pid_);
  if (err_) std::fclose(err_);
}

bool ChildProcess::wait_for(const std::string& text) {
  char line[4096];
  while (err_ && std::fgets(line, sizeof line, err_)) {
    log_ += line;
    if (std::string(line).find(text) != std::string::npos) return true;
  }
  return false;
}

void ChildProcess::interrupt(int signal) { kill(pid_, signal); }

int ChildProcess::exit_code() {
  if (reaped_) return code_;
  wait_for("\x01never");
  int status = 0;
  waitpid(pid_, &status, 0);
  reaped_ = true;
  code_ = exit_code_of(status);
  return code_;
}

}  // namespace mjray::test
