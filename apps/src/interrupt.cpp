#include "fsi_app/interrupt.hpp"

#include <csignal>

namespace fsi::app {

namespace {

volatile std::sig_atomic_t received_signal = 0;
struct sigaction previous_int, previous_term;

void record(int signal) {
  received_signal = signal;
}

} // namespace

InterruptGuard::InterruptGuard() {
  received_signal = 0;
  struct sigaction action = {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND; // a second signal ends the process at once
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int InterruptGuard::received() const {
  return received_signal;
}

} // namespace fsi::app
