#pragma once
// Implicit steps of a nodal field's equation C dT/dt = L(T) + s (core/FieldOperator.hpp: C the capacity per volume,
// L the blocks' conduction, s the surface conditions and, after a force evaluation, the blocks' sources such as
// plastic heating). Backward Euler over a step, C (T - T_n) / dt = L(T) + s, or the steady L(T) + s = 0, at the free
// nodes; the prescribed ones take the step end's values. Newton iterations, each a Jacobi-preconditioned BiCGStab
// solve (L is linear: one iteration converges to the Krylov tolerance). Used by ImplicitDiffusion (thermal only) and
// by the quasi-static mechanics solvers that advance Temperature beside the displacement (staggered: the converged
// mechanics of the step, then its heat). The solver never knows which terms sit behind the field.
#include <string>
#include <vector>

namespace pf {

class Model;

struct ImplicitFieldOptions {
  double relativeTolerance = 1e-6;  // of the step's initial residual (transient) or of Peridigm's reaction (steady)
  double absoluteTolerance = 0.0;   // > 0: used instead of the relative rule (Peridigm's)
  int maxIterations = 10;           // Newton iterations per step
  bool transient = false;           // Backward Euler; else steady
  bool verbose = false;             // print every iteration's residual
  std::string where;                // the deck's solver list, for messages
  std::string transientBy;          // the deck's setting that asks for the transient step, for messages
};

class ImplicitFieldStep {
 public:
  // InputError naming `o.where` when the field has no term (steady: no block conducts it) or, transient, a point
  // lacks a capacity. Collective.
  ImplicitFieldStep(const Model& model, std::string field, ImplicitFieldOptions o);
  struct Outcome {
    int iterations = 0;
    double residual = 0.0, tolerance = 0.0;
  };
  // From the committed field to the step end t (previous time tPrev; the prescribed conditions those of the last
  // applyPrescribed, at t): the field's trial values and its rate output (Flux_Divergence = L(T)) set, the ghosts left
  // to the next evaluation. With mechanicsEvaluated the step's force evaluation at its converged state came first and
  // the blocks' sources read its trial state. Call before Model::commit. SolverFailure when the tolerance is missed.
  Outcome advance(Model& model, double tPrev, double t, bool mechanicsEvaluated);
  // Newton iterations of the advances so far (a deterministic work count).
  long iterationsTaken() const { return taken_; }

 private:
  std::string field_;
  ImplicitFieldOptions opt_;
  bool heats_ = false;
  long taken_ = 0;
  std::vector<double> T_, rate_;
};

}  // namespace pf
