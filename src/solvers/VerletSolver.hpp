#pragma once
// Explicit velocity-Verlet (central difference) time integration with the lumped density. The time step is
// "Fixed dt" or Safety Factor x Peridigm's critical step estimate (default) or the Gershgorin bound
// 2/sqrt(max_i bound_i/rho_i). check(): a step above the bound warns, above kRefuseFactor x the bound is an
// input error unless Allow Unstable Time Step; a
// non-finite displacement, velocity or force stops the run (SolverFailure) before the step is reported. With
// `Solve For Temperature` the field takes explicit sub-steps after each force evaluation (ExplicitFieldStep), with
// `Solve For Displacement` false only those (a thermal-only run).
#include <memory>

#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

class ExplicitFieldStep;

struct VerletOptions {
  double fixedDt = 0.0;       // > 0: use this dt
  double safetyFactor = 0.8;  // used when fixedDt == 0
  bool peridigmEstimate = true;  // without fixedDt: Peridigm's critical step (PeridigmTimeStep.hpp), else the bound
  bool allowUnstable = false; // accept fixedDt > kRefuseFactor x the stable step
  bool prescribedHalfKick = true;  // Peridigm's velocity of a prescribed component (VerletPeridigm.hpp)
  std::string where;          // the deck list, for input errors ("input.xml: Solver/Verlet")
};

class VerletSolver : public Solver {
 public:
  explicit VerletSolver(VerletOptions o) : opt_(o) {}
  static SolverEntry entry();
  std::string name() const override { return "Verlet"; }
  // Fixed dt against the stable step (warns or refuses; a run at rest whose few steps cannot amplify round-off
  // beyond 1e6 only warns, RunStart); the one-argument form checks as for a body in motion.
  void check(const Model& model) const override { check(model, RunStart{}); }
  void check(const Model& model, const RunStart& start) const override;
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;
  // Gershgorin estimate, before the safety factor; freeOnly: over the points with a free component only
  // (infinity if there is none).
  static double stableTimeStep(const Model& model, bool freeOnly = false);
  // The Gershgorin bound is conservative, so a Fixed dt somewhat above it may still be stable (it warns);
  // at twice the bound the highest mode of a uniform lattice is already amplified every step, so more
  // than that is refused unless the user insists.
  static constexpr double kRefuseFactor = 2.0;

 private:
  // Fixed dt, or Safety Factor x the stable step (the mechanics', or the field's in a thermal-only run).
  double timeStep(const Model& model, const ExplicitFieldStep* heat) const;
  // The number of steps over `duration` at dt (dt then lands on the end time unless fixed), or a resumed run's dt
  // and count.
  long stepCount(double duration, double& dt, const SolverResume* resume) const;
  // Whether dt is shortened to end on the end time (the stiffness bound, or a thermal-only run's field step), not
  // Peridigm's floor of the steps (a Fixed dt, or its critical step).
  bool landsOnEnd() const {
    return opt_.fixedDt <= 0 && !(opt_.peridigmEstimate && advances("Displacement"));
  }
  // The Temperature field's explicit step when the deck has Verlet advance it (the field then marked solved), or null.
  std::unique_ptr<ExplicitFieldStep> heatStep(Model& model) const;
  void evaluate(Model& model, ExplicitFieldStep* heat, long step, double t, double dt, const std::vector<double>& y,
                const std::vector<double>& v, std::vector<double>& f) const;
  VerletOptions opt_;
};

}  // namespace pf
