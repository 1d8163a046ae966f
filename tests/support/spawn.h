#pragma once
/// Starting a program from a test: the fork and exec every test helper that runs one shares.

#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace mjray::test {

/// Starts argv[0] (a path: no PATH search) with the arguments that follow. `in_child` runs in
/// the new process before the exec, to point its descriptors elsewhere; it must only make
/// system calls (the test's other threads may hold the allocator's lock). The pid, or -1.
pid_t spawn(const std::vector<std::string>& argv, const std::function<void()>& in_child = {});

/// Opens `path` for appending (created if need be) as the process's stdout and stderr: for
/// `in_child`.
void log_output_to(const char* path);

/// Kills (SIGKILL) and reaps a child that is still running; nothing for pid ≤ 0.
void kill_and_reap(pid_t pid);

/// The exit code of a waitpid status; 128 + N when signal N ended the process.
int exit_code_of(int status);

}  // namespace mjray::test
