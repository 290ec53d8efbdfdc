#include "io/stop_signal.hpp"

#include <csignal>

namespace bpm {
namespace {
volatile std::sig_atomic_t received = 0;

void record_stop_signal(int signal) {
  received = signal;
}
}  // namespace

void install_stop_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal_received() {
  return received;
}

}  // namespace bpm
