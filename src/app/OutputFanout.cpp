#include "OutputFanout.hpp"

#include <csignal>
#include <sstream>

#include "core/StopSignal.hpp"

namespace pf {

void OutputFanout::onStep(const StepReport& r, const std::vector<double>& u, const std::vector<double>& v,
                          const std::vector<double>& f) {
  for (auto& m : managers) m->onStep(r, u, v, f);
  if (interfaces && !managers.empty() && managers.front()->wroteExodusStep()) interfaces->write(r.time, u);
  if (checkpointer) checkpointer->onStep(r, u, v, f);
  // After the step is written: what was converged is kept. All ranks agree (a signal may reach one rank,
  // or the ranks at different steps), so all stop here together.
  const int signal = static_cast<int>(comm_.max(static_cast<double>(stopSignal())));
  if (signal == 0) return;
  std::ostringstream what;
  what << "stopped by " << (signal == SIGINT ? "SIGINT" : "SIGTERM") << " at t = " << r.time;
  throw Interrupted(signal, what.str());
}

void OutputFanout::finish() {
  for (auto& m : managers) m->finish();
}

void OutputFanout::abandon(const std::string& verb, const std::string& line) noexcept {
  for (auto& m : managers) m->abandon(verb, line);
}

}  // namespace pf
