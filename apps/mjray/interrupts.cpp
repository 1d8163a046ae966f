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
std::atomic<bool> g_exit_on_interrupt{false};

extern "C" void on_interrupt(int) {
  // _exit is async-signal-safe; nothing is half-written while g_exit_on_interrupt is set.
  if (g_exit_on_interrupt) _exit(kInterruptedStatus);
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
  g_exit_on_interrupt = true;
  if (g_interrupted) {
    std::fflush(nullptr);
    _exit(kInterruptedStatus);
  }
}

ExitOnInterrupt::~ExitOnInterrupt() { g_exit_on_interrupt = false; }

}  // namespace mjray
