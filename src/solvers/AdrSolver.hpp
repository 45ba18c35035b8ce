#pragma once
// Adaptive dynamic relaxation (Kilic & Madenci 2010) for quasi-static load steps: a damped pseudo-time
// march with a diagonal fictitious density from the stiffness bound (stable at unit pseudo-time step)
// and a damping coefficient from the local Rayleigh quotient. A load step converges when the residual
// (force, free dofs) is below Relative Tolerance x the load scale (reaction + body force) or below the
// Absolute Tolerance; after Maximum Iterations it fails with SolverFailure.
#include <string>

#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

struct AdrOptions {
  double relativeTolerance = 1e-6;  // of the reaction / applied-load norm
  double absoluteTolerance = 0.0;   // on the residual force-density norm (Peridigm QuasiStatic meaning)
  int maxIterations = 100000;
  double safetyFactor = 1.0;        // multiplies the fictitious density
  bool verbose = false;             // print the residual history of every step
  bool loadBalance = false;         // Li & Geng's loading-balance correction (YieldRounds.hpp)
  double loadBalanceTolerance = 1e-6;  // its yield tolerance (YieldRounds.hpp, kYieldTolerance)
  bool loadBalanceFromSurface = false;  // its set starts with the points on their surface (else empty, the paper's)
  std::string where;                // the deck list, for input errors ("input.xml: Solver/Adaptive Dynamic Relaxation")
};

class AdrSolver : public Solver {
 public:
  explicit AdrSolver(AdrOptions o) : opt_(o) {}
  static SolverEntry entry();
  std::string name() const override { return "Adaptive Dynamic Relaxation"; }
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;
  // Loading Balance Correction needs every block's material to support it (Material::supportsYieldRounds).
  void check(const Model& model) const override;

  // Relaxes u (prescribed values at t already set, free ones predicted) to equilibrium at time t.
  // uStepStart: the converged state the step started from (the damping estimate works on u - uStepStart).
  // Writes trial state only; throws SolverFailure after Maximum Iterations or at the first non-finite
  // residual (state rolled back). step: the load step, for messages. loadFloor: see loadScale.
  struct StepResult {
    int iterations;
    double residual, tolerance, load;
  };
  StepResult relax(Model& model, std::vector<double>& u, double t, const std::vector<double>& uStepStart,
                   long step, double loadFloor) const;

 private:
  AdrOptions opt_;
};

}  // namespace pf
