#pragma once
// Ctrl-C and SIGTERM: the first one asks the command to stop (runs and sweeps stop at their next progress report,
// temporary directories are removed, the exit code is 128 + the signal); a second one ends the process at once.

namespace mdr::cli {

/// Installs the handlers for SIGINT and SIGTERM.
void install_interrupt_handlers();

/// The signal received (SIGINT or SIGTERM), or 0 while none was.
int received_signal();

/// Throws mdr::Interrupted once a signal was received; safe on any thread.
void throw_if_interrupted();

}  // namespace mdr::cli
