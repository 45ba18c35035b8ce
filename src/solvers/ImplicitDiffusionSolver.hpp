#pragma once
// Peridigm's "ImplicitDiffusion": the steady state of the Temperature field at each load time,
//   L(T)_i = 0 at the free nodes, T = its Prescribed Temperature elsewhere,
// L being the blocks' conduction operators (materials/HeatConduction.hpp; Flux_Divergence is L(T)). Newton
// iterations, each a Jacobi-preconditioned BiCGStab solve (ScalarKrylov.hpp; L is linear, so one iteration
// converges up to the Krylov tolerance), until |L(T)| over the free nodes is at most Relative Tolerance times the
// norm of L(T) V over the prescribed nodes at the step's start (Peridigm's reaction rule) or, if given, Absolute
// Tolerance. `Time Integration` = `Backward Euler` (Periforge's) makes it transient: rho c (T - T_n) / dt = L(T) over
// each load step, converged to Relative Tolerance of the step's initial residual. The displacement stays as it is.
#include <string>

#include "ImplicitFieldStep.hpp"
#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {


class ImplicitDiffusionSolver : public Solver {
 public:
  explicit ImplicitDiffusionSolver(ImplicitFieldOptions o) : opt_(std::move(o)) {}
  static SolverEntry entry();  // "ImplicitDiffusion"
  std::string name() const override { return "ImplicitDiffusion (steady heat conduction)"; }
  void check(const Model& model) const override;
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;

 private:
  ImplicitFieldOptions opt_;  // its load step's options (ImplicitFieldStep.hpp)
};

}  // namespace pf
