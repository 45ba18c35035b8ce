#include "BreakRounds.hpp"

#include <cstdio>

#include "Solver.hpp"

namespace pf {

bool solveWithBreakRounds(Model& model, std::vector<double>& u, const std::function<bool()>& solve, double t) {
  if (!model.hasDamage()) return solve();
  model.beginBreakRounds();
  std::vector<double> f(model.numDofs());
  try {
    for (int round = 1;; ++round) {
      model.setBreaking(false);
      if (!solve()) {
        model.endBreakRounds();
        return false;
      }
      // The converged state decides: every bond stretched past s_c there breaks now.
      model.setBreaking(true);
      model.internalForce(u.data(), f.data());
      const double added = model.adoptBreaks();
      if (added == 0.0) return true;  // trial = this evaluation: the base set, in equilibrium
      if (round == kMaxBreakRounds) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "load step at t = %g: bonds still break after %d re-equilibrations (%.0f in the last); "
                      "use smaller load steps", t, kMaxBreakRounds, added);
        throw SolverFailure(msg);
      }
    }
  } catch (...) {
    model.endBreakRounds();
    throw;
  }
}

}  // namespace pf
