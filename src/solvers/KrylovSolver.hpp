#pragma once
// Part of the NOX adapter: the Krylov solve of the Newton step. The operator is given by its action on plain
// arrays (matrix-free) and solved by GMRES (Gmres.hpp); the preconditioner (MueLu's smoothed aggregation,
// MueLuPreconditioner.hpp, or an Ifpack2 factorisation, per the deck's "Linear Solver" list) is built once, on the
// first solve, from the assembled pair stiffness (PairStiffness.hpp) and reused by every later solve of the engine.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Thyra_VectorSpaceBase_decl.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pf {

class Model;
struct NewtonWork;

// y = J dx on owned dofs; false when it cannot be evaluated (a material failure).
using TangentAction = std::function<bool(const double* dx, double* y)>;

struct KrylovOutcome {
  bool converged = false;
  bool failed = false;  // the action failed: the direction is unusable
  int iterations = 0;
};

class KrylovSolver {
 public:
  // Collective. shift: 3 per owned node (a Newmark step's mass term) or null; where: the deck's solver list;
  // work: counts and times the solves, preconditioner builds and applications (null: not counted).
  KrylovSolver(const Model& model, double precBondRadius, const std::vector<double>* shift, std::string where,
               NewtonWork* work = nullptr);
  ~KrylovSolver();
  // The pair stiffness' mean free diagonal: the weight of prescribed rows in the residual.
  double scale() const;
  // The space of the Newton vectors (owned dofs, global id 3 * point + component), for NOX's Thyra vectors.
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space() const;
  // Solves J dx = rhs from dx = 0 by GMRES (Gmres.hpp) with the list's "Tolerance" (relative to |rhs|), "Max
  // Iterations", "Size of Krylov Subspace" and "Preconditioner" (linearSolverChoice, NoxParameters.hpp). Collective.
  // linearResidual (or null): receives rhs - J dx without another product (so J dx = rhs - linearResidual).
  KrylovOutcome solve(const TangentAction& J, const double* rhs, double* dx, Teuchos::ParameterList& linearSolver,
                      double* linearResidual = nullptr);
  // out = M⁻¹ in with the preconditioner of the solves (built from the list's choice if no solve has built it yet;
  // the identity for "None"). NOX's preconditioned nonlinear CG direction asks for it. Collective.
  void applyPreconditioner(const double* in, double* out, Teuchos::ParameterList& linearSolver);
  // True on every rank iff `local` is on every rank. Collective.
  bool onEveryRank(bool local) const;

 private:
  struct Impl;
  void ensurePreconditioner(Teuchos::ParameterList& linearSolver);
  std::unique_ptr<Impl> impl_;
};

}  // namespace pf
