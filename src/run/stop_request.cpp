#include "run/stop_request.hpp"

#include <csignal>

namespace cambrian {

namespace {

// the signal that asked for a stop; 0 while none did
volatile std::sig_atomic_t stop_signal = 0;

// async-signal-safe: only stores the number
extern "C" void onStopSignal(int signal_number) {
  stop_signal = signal_number;
}

}  // namespace

void installStopSignals() {
  // the same handler for both signals, restarting interrupted system calls
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGUSR1, &action, nullptr);
}

bool stopRequested() {
  return stop_signal != 0;
}

const char* stopSignalName() {
  switch (stop_signal) {
    case SIGTERM:
      return "SIGTERM";
    case SIGUSR1:
      return "SIGUSR1";
    default:
      return "";
  }
}

void clearStopRequest() {
  stop_signal = 0;
}

}  // namespace cambrian
