#pragma once
// One nonlinear solve by NOX's line-search Newton method with a Jacobian-free Krylov solve, shared by the
// quasi-static (NoxQuasiStaticSolver) and the Newmark (ImplicitSolver) solvers. It solves, on free dofs,
//   f(u) + b(t) - c (u - u~) = 0          (c = 0: equilibrium; c = rho / (beta dt^2): a Newmark step)
// and u = u(t) on prescribed ones; the preconditioner (pair stiffness + c) is built once per engine.
#include <memory>
#include <string>
#include <vector>

#include "NewtonWork.hpp"
#include "core/ParamTree.hpp"

namespace pf {

class Model;
class KrylovSolver;

struct NewtonKrylovOptions {
  double relativeTolerance = 1e-10;  // of the load scale (reaction + body force + inertia), as ADR's
  double absoluteTolerance = 0.0;    // on the residual force-density norm, or with peridigmAbsolute:
  // on Peridigm's QuasiStatic measure ||(f + b) V||_2 + 20 ||(f + b) V||_inf (ResidualNorms::peridigmQuasiStatic)
  bool peridigmAbsolute = false;
  int maxIterations = 30;            // Newton iterations per solve
  bool verbose = false;              // print NOX's residual history
  // The Krylov operator: the materials' exact directional derivative (forceDerivative) where every block's
  // material has one, else a forward difference of the force; false: the forward difference always (the
  // deck's `Jacobian` = `Finite Difference`, for comparisons).
  bool exactJacobian = true;
  // The preconditioner matrix keeps only each node's bonds up to this many times its shortest bond
  // (the grid spacing), stiffened to keep the second moment (the smooth-mode stiffness). Measured: at
  // delta/dx = 5 a radius of 3 dx halves the wall time (20 % more Krylov iterations); at delta/dx = 3 in 2D
  // it keeps every bond, and cutting further there cost more iterations than it saved; in 3D 2 dx wins.
  // 0: by dimension (defaultPreconditionerRadius).
  double precBondRadius = 0.0;
  // With the adaptive Krylov tolerance: the first solve of a step asks for no less than this times the residual
  // contraction the previous step's first Newton iteration reached (the nonlinear error its Newton step leaves:
  // solving the linear system far below it is wasted); 0: off (a tenth of what the force test needs, as later).
  double firstSolveForcing = 0.0;
  ParamTree nox;                     // "Direction", "Line Search", "Printing", ... passed to NOX
  std::string where;                 // the deck's solver list ("input.xml: Solver/NOXQuasiStatic"), for errors
};

// Throws InputError (naming opt.where and the parameter) when the NOX lists ask for a Krylov method or
// preconditioner the engine does not have; called when the deck is read, not at the first solve.
void checkLinearSolver(const NewtonKrylovOptions& opt);

// The inertia term of a Newmark step: c per dof (rho / (beta dt^2), the same at every call of one engine,
// since the preconditioner holds it) and the predictor u~. Prescribed dofs ignore both.
struct Inertia {
  std::vector<double> coefficient;
  std::vector<double> predictor;
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0, linearIterations = 0;
  double residual = 0, tolerance = 0;  // force residual (free dofs) and the relative test's bound on it [N]
  double residualDensity = 0;          // the same residual as force density
  double load = 0;                     // the last residual's load scale (ResidualNorms::load)
  double peridigmResidual = 0;         // the last residual in Peridigm's QuasiStatic measure (ResidualNorms)
};

// Rank 0 prints work.summary() (the end of a run).
void printWork(const Model& model, const NewtonWork& work);

class NewtonKrylov {
 public:
  explicit NewtonKrylov(NewtonKrylovOptions o);
  ~NewtonKrylov();
  // From u (prescribed components already at their values at t, free ones predicted) to the solution at
  // t, within maxIterations. Writes the materials' trial state only: the caller commits or rolls back.
  // inertia: null for equilibrium; otherwise the same coefficients at every call. loadFloor: the relative
  // test's load scale is never below it (loadScale in LoadStepping.hpp).
  NewtonOutcome solve(Model& model, std::vector<double>& u, double t, const Inertia* inertia = nullptr,
                      double loadFloor = 0.0);
  // solve() inside the damage break rounds (BreakRounds.hpp: on convergence the caller commits, then calls
  // model.endBreakRounds()); iterations summed over the rounds. Without damage: one solve().
  NewtonOutcome solveWithBreaks(Model& model, std::vector<double>& u, double t, const Inertia* inertia = nullptr,
                                double loadFloor = 0.0);
  const NewtonKrylovOptions& options() const { return opt_; }
  // After a converged solve: the internal force density at its u if the model's trial state is still that of the
  // last residual there (a commit then needs no evaluation of its own); null otherwise, after the damage break
  // rounds (they evaluate between the solves), or once the model has been called by anyone else.
  const std::vector<double>* convergedForce(const std::vector<double>& u) const {
    return converged_ && lastModelCall_ == work_.modelCalls() && u == convergedU_ ? &convergedForce_ : nullptr;
  }
  // The engine's work so far (all its solves).
  const NewtonWork& work() const { return work_; }
  // The last first Newton iteration's residual contraction that `First Solve Forcing` reads (< 0: none yet): the
  // solver carries it across a restart.
  double& firstIterationContraction() { return contraction_; }

 private:
  NewtonKrylovOptions opt_;
  std::unique_ptr<KrylovSolver> krylov_;  // pair stiffness and its preconditioner: built on first use, kept
  NewtonWork work_;
  double forcing(double need, double r, int k, double& first);
  void keepConvergedForce(const std::vector<double>* f, const std::vector<double>& u);  // null: none
  double contraction_ = -1;  // |F_1| / |F_0| of the last solve's first Newton iteration; < 0: none yet
  bool converged_ = false;
  long lastModelCall_ = -1;
  std::vector<double> convergedU_, convergedForce_;
};

}  // namespace pf
