#include "StopSignal.hpp"

#include <csignal>

namespace pf {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void onStopSignal(int signal) {
  received = signal;
  std::signal(signal, SIG_DFL);  // async-signal-safe; the next one ends the process
}

}  // namespace

void installStopHandlers() {
  std::signal(SIGTERM, onStopSignal);
  std::signal(SIGINT, onStopSignal);
}

int stopSignal() { return received; }

}  // namespace pf
