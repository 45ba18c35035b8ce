#include "YieldRounds.hpp"

#include <cstdio>

#include "Solver.hpp"
#include "model/Model.hpp"

namespace pf {

int yieldRounds(const std::function<void()>& relax, const std::function<double()>& admit, double t) {
  for (int round = 1;; ++round) {
    relax();
    const double added = admit();
    if (added == 0.0) return round;
    if (round == kMaxYieldRounds) {
      char msg[240];
      std::snprintf(msg, sizeof msg,
                    "load step at t = %g: loading-balance correction: points still yield after %d relaxations "
                    "(%.0f admitted in the last); use smaller load steps", t, kMaxYieldRounds, added);
      throw SolverFailure(msg);
    }
  }
}

int solveWithYieldRounds(Model& model, const std::function<void()>& relax, double t, double tol, bool fromSurface) {
  model.beginYieldRounds(fromSurface ? tol : -1.0);
  try {
    return yieldRounds(relax, [&] { return model.admitYielding(tol); }, t);
  } catch (...) {
    model.endYieldRounds();
    throw;
  }
}

}  // namespace pf
