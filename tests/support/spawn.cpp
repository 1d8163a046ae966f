#include "support/spawn.h"

#include <csignal>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace mjray::test {

pid_t spawn(const std::vector<std::string>& argv, const std::function<void()>& in_child) {
  // Compute the argument array before the fork: the child may not allocate.
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (in_child) in_child();
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

void log_output_to(const char* path) {
  const int fd = ::open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
  ::dup2(fd, 1);
  ::dup2(fd, 2);
}

void kill_and_reap(pid_t pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
}

int exit_code_of(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

}  // namespace mjray::test
