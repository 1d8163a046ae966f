#include "interrupts.h"

#include <atomic>
#include <csignal>
#include <cstdio>

#include <unistd.h>

namespace mjray {

namespace {

/// The exit status of a run the user interrupted, as a shell reports one ended by SIGINT.
constexpr int kInterruptedStatus = 130;

std::atomic<bool> g_interrupted{false};
std::atomic<int> g_exit_scopes{0};  // ExitOnInterrupt scopes alive, on any thread
// The handler reads both: lock-free atomics are what a signal handler may touch.
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

extern "C" void on_interrupt(int) {
  // _exit is async-signal-safe; nothing is half-written while a scope is alive.
  if (g_exit_scopes > 0) _exit(kInterruptedStatus);
  g_interrupted = true;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() { return g_interrupted; }

ExitOnInterrupt::ExitOnInterrupt() {
  ++g_exit_scopes;
  // An interrupt that came before (while the last frame's image was written) ends it now.
  if (g_interrupted) {
    std::fflush(nullptr);
    _exit(kInterruptedStatus);
  }
}

ExitOnInterrupt::~ExitOnInterrupt() { --g_exit_scopes; }

}  // namespace mjray
