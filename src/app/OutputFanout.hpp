#pragma once
// Hands each reported step to every output list's manager (Output, or Output1, Output2, ...), then stops
// the run, on every rank at the same step, when any rank received SIGTERM/SIGINT (throws Interrupted).
// finish() and abandon() pass the run's outcome on to every manager's files.
#include <memory>
#include <vector>

#include "output/InterfaceOutput.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

class OutputFanout : public StepObserver {
 public:
  explicit OutputFanout(const Communicator& comm) : comm_(comm) {}
  std::vector<std::unique_ptr<OutputManager>> managers;
  InterfaceOutput* interfaces = nullptr;  // or null; writes with the first manager's Exodus steps
  StepObserver* checkpointer = nullptr;  // or null; called after the managers, so a checkpoint holds the step's output
  void onStep(const StepReport& r, const std::vector<double>& u, const std::vector<double>& v,
              const std::vector<double>& f) override;
  void finish();                                                          // collective
  void abandon(const std::string& verb, const std::string& line) noexcept;  // see OutputManager

 private:
  Communicator comm_;
};

}  // namespace pf
