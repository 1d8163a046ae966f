#include "support/child_process.h"

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

namespace mjray::test {

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  int fds[2];
  if (pipe(fds) != 0) return;
  pid_ = fork();
  if (pid_ == 0) {
    dup2(fds[1], 2);
    close(fds[0]);
    close(fds[1]);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  close(fds[1]);
  err_ = fdopen(fds[0], "r");
}

ChildProcess::~ChildProcess() {
  if (!reaped_ && pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
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
  code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return code_;
}

}  // namespace mjray::test
