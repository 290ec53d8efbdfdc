#pragma once
/// SIGINT (Ctrl-C) and SIGTERM during `bpmkit run`: the handler only records the signal (an
/// async-signal-safe store to a sig_atomic_t); the step loop checks it after each step, writes a
/// checkpoint and ends the run as "interrupted". The handler is one-shot (SA_RESETHAND): a second
/// Ctrl-C kills the process at once.
namespace bpm {

void install_stop_signal_handlers();
/// The signal received since installation (SIGINT or SIGTERM), 0 if none.
int stop_signal_received();

}  // namespace bpm
