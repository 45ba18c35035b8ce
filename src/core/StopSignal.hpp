#pragma once
// SIGTERM and SIGINT ask a run to stop between two steps instead of killing it mid-write: the handler only
// records the signal (no I/O in a handler) and restores the default action, so a second signal kills as
// usual. The run polls stopSignal() after each step and throws Interrupted (see OutputFanout); a solver whose
// step can take minutes (ADR's relaxation) polls it within the step too.
#include <stdexcept>
#include <string>

namespace pf {

void installStopHandlers();
int stopSignal();  // 0, or the last SIGTERM/SIGINT received

class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

}  // namespace pf
