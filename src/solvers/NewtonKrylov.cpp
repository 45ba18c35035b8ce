#include "NewtonKrylov.hpp"

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <NOX.H>
#include <NOX_Epetra.H>
#include <NOX_Epetra_MatrixFree.H>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "BreakRounds.hpp"
#include "LoadStepping.hpp"
#include "NoxPairPreconditioner.hpp"
#include "NoxParameters.hpp"
#include "core/Material.hpp"
#include "model/Model.hpp"
#include "parallel/CommunicatorImpl.hpp"

namespace pf {
namespace {

// NOX's view of one solve: x holds the displacements (3 per owned node); F is -(f + b - c (x - u~)) on
// free dofs (c = 0 without inertia) and s (x - xbar) on prescribed ones, s the mean preconditioner
// diagonal so that both kinds of rows are alike in scale. The inertial force -c (x - u~) counts as load:
// the norms see b - c (x - u~) where they see the body force.
class StepProblem : public NOX::Epetra::Interface::Required, public NOX::Epetra::Interface::Preconditioner {
 public:
  StepProblem(Model& model, double t, std::vector<double> xbar, double scale, const Inertia* inertia)
      : model_(model), xbar_(std::move(xbar)), scale_(scale), inertia_(inertia), u_(model.numDofs()),
        f_(model.numDofs()), fResidual_(model.numDofs()), b_(model.numDofs()), load_(model.numDofs()),
        loadResidual_(model.numDofs()) {
    model.bodyForce(t, b_.data());
    load_ = b_;
  }

  bool computeF(const Epetra_Vector& x, Epetra_Vector& F, const FillType flag) override {
    const std::vector<char>& fixed = model_.prescribedMask();
    const int n = model_.numDofs();
    for (int k = 0; k < n; ++k) u_[k] = x[k];
    try {
      model_.internalForce(u_.data(), f_.data());
    } catch (const ConstitutiveFailure& e) {
      failure_ = e.what();
      return false;
    }
    if (inertia_)
      for (int k = 0; k < n; ++k)
        if (!fixed[k]) load_[k] = b_[k] - inertia_->coefficient[k] * (x[k] - inertia_->predictor[k]);
    for (int k = 0; k < n; ++k) F[k] = fixed[k] ? scale_ * (x[k] - xbar_[k]) : -(f_[k] + load_[k]);
    if (flag == Residual) {
      fResidual_ = f_;
      loadResidual_ = load_;
      if (onResidual_) onResidual_(norms());
    }
    return true;
  }
  // Called with the norms of every residual evaluation (NOX evaluates the accepted iterate last).
  void setOnResidual(std::function<void(const ResidualNorms&)> f) { onResidual_ = std::move(f); }

  bool computePreconditioner(const Epetra_Vector&, Epetra_Operator&, Teuchos::ParameterList*) override {
    return true;  // the pair stiffness is a fixed matrix, factored once per run (newton())
  }

  // Residual measures at the last residual evaluation (the current Newton iterate).
  ResidualNorms norms() const { return residualNorms(model_, fResidual_, loadResidual_); }
  const std::string& failure() const { return failure_; }

 private:
  Model& model_;
  std::vector<double> xbar_;
  double scale_;
  const Inertia* inertia_;
  std::vector<double> u_, f_, fResidual_, b_, load_, loadResidual_;  // load: b - c (x - u~)
  std::string failure_;
  std::function<void(const ResidualNorms&)> onResidual_;
};

// The Jacobian of StepProblem's residual, applied matrix-free: -df + c dx on free rows, s dx on prescribed ones.
// df is the materials' exact forceDerivative where all have one (and the deck did not ask for the difference,
// NewtonKrylovOptions::exactJacobian); otherwise a forward difference of the
// force whose perturbation is scaled to the model's length (1e-7 of the shortest bond): NOX's own
// matrix-free operator scales it by |x|, which is ~0 at the first load step and gives no derivative.
class TangentOperator : public Epetra_Operator, public NOX::Epetra::Interface::Jacobian {
 public:
  TangentOperator(Model& model, const Epetra_Map& map, double scale, const Inertia* inertia, bool exact)
      : model_(model), map_(map), scale_(scale), inertia_(inertia), exact_(exact && model.hasExactTangent()), u_(model.numDofs()),
        du_(model.numDofs()), df_(model.numDofs()), f0_(model.numDofs()), up_(model.numDofs()) {
    double shortest = std::numeric_limits<double>::max();
    for (double r : model.layout().family().refLength) shortest = std::min(shortest, r);
    double g = 0;
    double neg = -shortest;
    model.layout().comm().max(&neg, &g, 1);
    step_ = 1e-7 * (-g);
  }
  bool exact() const { return exact_; }

  bool computeJacobian(const Epetra_Vector& x, Epetra_Operator&) override {
    for (int k = 0; k < model_.numDofs(); ++k) u_[k] = x[k];
    if (exact_) return true;
    try {
      model_.internalForce(u_.data(), f0_.data());
    } catch (const ConstitutiveFailure&) {
      return false;
    }
    return true;
  }
  int Apply(const Epetra_MultiVector& X, Epetra_MultiVector& Y) const override {
    const std::vector<char>& fixed = model_.prescribedMask();
    const int n = model_.numDofs();
    for (int col = 0; col < X.NumVectors(); ++col) {
      for (int k = 0; k < n; ++k) du_[k] = X[col][k];
      if (exact_) {
        if (!model_.forceDerivative(u_.data(), du_.data(), df_.data())) return -1;
      } else {
        double local = 0, vmax = 0;
        for (int k = 0; k < n; ++k) local = std::max(local, std::fabs(du_[k]));
        model_.layout().comm().max(&local, &vmax, 1);
        if (vmax == 0) {
          std::fill(df_.begin(), df_.end(), 0.0);
        } else {
          const double h = step_ / vmax;
          for (int k = 0; k < n; ++k) up_[k] = u_[k] + h * du_[k];
          try {
            model_.internalForce(up_.data(), df_.data());
          } catch (const ConstitutiveFailure&) {
            return -1;
          }
          for (int k = 0; k < n; ++k) df_[k] = (df_[k] - f0_[k]) / h;
        }
      }
      for (int k = 0; k < n; ++k)
        Y[col][k] = fixed[k] ? scale_ * du_[k] : -df_[k] + (inertia_ ? inertia_->coefficient[k] * du_[k] : 0.0);
    }
    return 0;
  }
  int SetUseTranspose(bool) override { return -1; }
  int ApplyInverse(const Epetra_MultiVector&, Epetra_MultiVector&) const override { return -1; }
  double NormInf() const override { return 0.0; }
  const char* Label() const override { return "Periforge tangent"; }
  bool UseTranspose() const override { return false; }
  bool HasNormInf() const override { return false; }
  const Epetra_Comm& Comm() const override { return map_.Comm(); }
  const Epetra_Map& OperatorDomainMap() const override { return map_; }
  const Epetra_Map& OperatorRangeMap() const override { return map_; }

 private:
  Model& model_;
  const Epetra_Map& map_;
  double scale_, step_ = 0;
  const Inertia* inertia_;
  bool exact_;
  std::vector<double> u_;
  mutable std::vector<double> du_, df_, f0_, up_;
};

// Converged when the force residual on free dofs is below the relative tolerance times the load scale
// (loadScale, the same test ADR uses) or the force-density residual is below the absolute tolerance.
class ForceResidualTest : public NOX::StatusTest::Generic {
 public:
  ForceResidualTest(const StepProblem& p, double rel, double abs, double loadFloor)
      : problem_(p), rel_(rel), abs_(abs), floor_(loadFloor) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    if (!solver.getSolutionGroup().isF()) return status_ = NOX::StatusTest::Unevaluated;
    last_ = problem_.norms();
    tol_ = rel_ * loadScale(last_, floor_);
    const bool ok = last_.residual <= tol_ || (abs_ > 0 && last_.residualDensity <= abs_) || last_.residual == 0.0;
    return status_ = ok ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override {
    for (int i = 0; i < indent; ++i) os << ' ';
    os << "force residual " << last_.residual << " N (tolerance " << tol_ << " N), density "
       << last_.residualDensity;
    if (abs_ > 0) os << " (tolerance " << abs_ << ")";
    os << "\n";
    return os;
  }
  // The factor by which the residual r must still fall to pass (either criterion), 0 if unknown.
  double reductionNeeded(const ResidualNorms& r) const {
    double need = 0;
    if (r.residual > 0) need = std::max(need, rel_ * loadScale(r, floor_) / r.residual);
    if (abs_ > 0 && r.residualDensity > 0) need = std::max(need, abs_ / r.residualDensity);
    return need;
  }
  const ResidualNorms& last() const { return last_; }
  double tolerance() const { return tol_; }

 private:
  const StepProblem& problem_;
  double rel_, abs_, floor_, tol_ = 0;
  ResidualNorms last_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace

struct NewtonKrylov::Linear {
  Teuchos::RCP<Epetra_Map> map;        // owned dofs, global id 3 * point + component
  Teuchos::RCP<Epetra_CrsMatrix> M;    // preconditioner matrix (pair stiffness + inertia)
  Teuchos::RCP<Epetra_Operator> prec;  // its Ifpack or ML preconditioner, built once for the engine's life
};

NewtonKrylov::NewtonKrylov(NewtonKrylovOptions o) : opt_(std::move(o)), linear_(std::make_unique<Linear>()) {}

NewtonKrylov::~NewtonKrylov() = default;

NewtonOutcome NewtonKrylov::solve(Model& model, std::vector<double>& u, double t, const Inertia* inertia,
                                  double loadFloor) {
  const int n = model.numDofs();
  Linear& lin = *linear_;
  if (lin.M.is_null()) {  // the pair stiffness depends on the reference configuration only: build it once
    std::vector<int> dofGids(n);
    for (int i = 0; i < model.numOwned(); ++i)
      for (int a = 0; a < 3; ++a) dofGids[3 * i + a] = 3 * model.layout().gids()[i] + a;
    lin.map = Teuchos::rcp(new Epetra_Map(-1, n, dofGids.data(), 0, model.layout().comm().impl().epetra));
    lin.M = pairMatrix(model, *lin.map, opt_.precBondRadius, inertia ? &inertia->coefficient : nullptr, &scale_);
  }
  const Epetra_Map& map = *lin.map;
  const double scale = scale_;

  std::vector<double> xbar(u);  // prescribed values were set by the predictor
  auto problem = Teuchos::rcp(new StepProblem(model, t, xbar, scale, inertia));
  Epetra_Vector x0(map);
  for (int k = 0; k < n; ++k) x0[k] = u[k];
  NOX::Epetra::Vector noxX0(x0, NOX::DeepCopy);

  bool adaptiveTolerance = false;
  auto params = noxParameters(opt_, model.layout().rank(), &adaptiveTolerance);
  Teuchos::ParameterList& print = params->sublist("Printing");
  Teuchos::ParameterList& ls = params->sublist("Direction").sublist("Newton").sublist("Linear Solver");
  // The preconditioner of the fixed pair stiffness (Ifpack ILU or ML) is built once per run and reused
  // by every Newton iteration of every load step: rebuilding it per step cost more than the Krylov solves.
  const std::string precType = ls.get<std::string>("Preconditioner");
  if (precType == "New Ifpack") {
    Teuchos::ParameterList& ifp = ls.sublist("Ifpack");
    setDefault(ifp, "fact: level-of-fill", 0);
    if (lin.prec.is_null()) lin.prec = factorIfpack(lin.M, ls.get<std::string>("Ifpack Preconditioner", "ILU"),
                                                    ls.get<int>("Overlap", 0), ifp);
  } else if (precType == "ML") {
    if (lin.prec.is_null()) lin.prec = buildMl(lin.M, ls.sublist("ML"));
  }
  Teuchos::RCP<Epetra_Operator> M = lin.M;
  if (!lin.prec.is_null()) {
    ls.set("Preconditioner", "User Defined");
    M = lin.prec;
  }

  auto tangent = Teuchos::rcp(new TangentOperator(model, map, scale, inertia, opt_.exactJacobian));
  auto linSys = Teuchos::rcp(new NOX::Epetra::LinearSystemAztecOO(print, ls, tangent, tangent, problem, M, noxX0));
  auto group = Teuchos::rcp(new NOX::Epetra::Group(print, problem, noxX0, linSys));

  auto force = Teuchos::rcp(new ForceResidualTest(*problem, opt_.relativeTolerance, opt_.absoluteTolerance, loadFloor));
  auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  combo->addStatusTest(force);
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(opt_.maxIterations)));
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));

  // Inexact Newton: each Krylov solve is asked only for a tenth of the reduction the force test still
  // needs, instead of a fixed 1e-9 that over-solves every step whose predictor is already close; Newton
  // stays quadratic while the residual is far from the tolerance.
  if (adaptiveTolerance)
    problem->setOnResidual([&ls, test = force.get()](const ResidualNorms& r) {
      const double need = test->reductionNeeded(r);
      if (need > 0) ls.set("Tolerance", std::clamp(0.1 * need, 1e-10, 1e-2));
    });

  NewtonOutcome out;
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  try {
    Teuchos::RCP<NOX::Solver::Generic> solver = NOX::Solver::buildSolver(group, combo, params);
    status = solver->solve();
    out.iterations = solver->getNumIterations();
    if (ls.isSublist("Output"))
      out.linearIterations = ls.sublist("Output").get<int>("Total Number of Linear Iterations", 0);
    const auto& sol = dynamic_cast<const NOX::Epetra::Vector&>(solver->getSolutionGroup().getX()).getEpetraVector();
    for (int k = 0; k < n; ++k) u[k] = sol[k];
  } catch (const std::exception& e) {
    status = NOX::StatusTest::Failed;
  }
  out.converged = status == NOX::StatusTest::Converged && force->getStatus() == NOX::StatusTest::Converged;
  out.residual = force->last().residual;
  out.residualDensity = force->last().residualDensity;
  out.tolerance = force->tolerance();
  out.load = force->last().load;
  return out;
}

NewtonOutcome NewtonKrylov::solveWithBreaks(Model& model, std::vector<double>& u, double t, const Inertia* inertia,
                                            double loadFloor) {
  NewtonOutcome o;
  int iterations = 0, linear = 0;
  o.converged = solveWithBreakRounds(model, u, [&] {
    o = solve(model, u, t, inertia, loadFloor);
    iterations += o.iterations;
    linear += o.linearIterations;
    return o.converged;
  }, t);
  o.iterations = iterations;
  o.linearIterations = linear;
  return o;
}

}  // namespace pf
