#pragma once
// Explicit velocity-Verlet (central difference) time integration with the lumped density. The time
// step is "Fixed dt" or Safety Factor x the Gershgorin bound 2/sqrt(max_i bound_i/rho_i).
#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

struct VerletOptions {
  double fixedDt = 0.0;       // > 0: use this dt
  double safetyFactor = 0.8;  // used when fixedDt == 0
};

class VerletSolver : public Solver {
 public:
  explicit VerletSolver(VerletOptions o) : opt_(o) {}
  static SolverEntry entry();
  std::string name() const override { return "Verlet"; }
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;
  static double stableTimeStep(const Model& model);  // Gershgorin estimate, before the safety factor

 private:
  VerletOptions opt_;
};

}  // namespace pf
