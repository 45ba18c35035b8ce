#pragma once
// Explicit (forward Euler) steps of a nodal field's equation C dT/dt = L(T) + s (core/FieldOperator.hpp: C the
// capacity per volume, L the blocks' conduction, s their sources such as plastic heating), for an explicit solver
// that advances the field beside (or instead of) the displacement. Staggered: over a solver step of length dt that
// has just evaluated its force at the step's end, the field goes from its committed value to the trial value of the
// step's end in m equal sub-steps, m the fewest with dt / m within the stable step min_i C_i / D_i (D_i the sum of
// point i's conduction coefficients: Gershgorin's disc of row i of C^-1 L lies in [-2 D_i / C_i, 0]). The sources
// are those of the step (constant over its sub-steps); prescribed values are the step end's. The solver never knows
// which terms sit behind the field.
#include <string>
#include <vector>

namespace pf {

class Model;

class ExplicitFieldStep {
 public:
  // Checks that every point has a capacity (InputError naming `where` otherwise); collective.
  ExplicitFieldStep(const Model& model, std::string field, const std::string& where);
  // The stable step min_i C_i / D_i times kSafety (infinity without conduction); collective.
  double stableStep() const { return stable_; }
  // Sub-steps for a step of length dt.
  long subSteps(double dt) const;
  // The trial field of the step's end from the committed one, its rate output and its change (the ghosts follow at the next evaluation). With
  // mechanicsEvaluated the step's force evaluation came first and the blocks' sources (plastic heating) read its trial
  // state; without (a thermal-only run) only the surface conditions heat. Call before Model::commit.
  void advance(Model& model, double dt, bool mechanicsEvaluated);
  // Sub-steps of the advances so far (a deterministic work count).
  long subStepsTaken() const { return taken_; }
  // Below the Gershgorin bound by a margin for the round-off of the capacity and coefficient sums.
  static constexpr double kSafety = 0.95;

 private:
  std::string field_;
  std::vector<double> capacity_, diag_, T_, rate_, source_, surface_;
  double stable_ = 0.0;
  bool conducts_ = false, heats_ = false;
  long taken_ = 0;
};

}  // namespace pf
