#pragma once
/// Ctrl-C and SIGTERM. While a render runs they ask it to stop, so that the partial image and
/// its state are kept; while work that cannot stop half-way and leaves nothing to keep runs
/// (the scene script, building the accelerator, the photon pass), they end the process at once.

namespace mjray {

/// Installs SIGINT and SIGTERM handlers that set the flag interrupted() reads.
void install_interrupt_handlers();
/// Whether the user asked to stop (Ctrl-C or SIGTERM).
bool interrupted();

/// While it lives, SIGINT and SIGTERM end the process with status 130 instead of setting the
/// flag; an interrupt that came before it does the same at its construction.
class ExitOnInterrupt {
 public:
  ExitOnInterrupt();
  ~ExitOnInterrupt();
  ExitOnInterrupt(const ExitOnInterrupt&) = delete;
  ExitOnInterrupt& operator=(const ExitOnInterrupt&) = delete;
};

}  // namespace mjray
