#include "NoxQuasiStaticSolver.hpp"

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <NOX.H>
#include <NOX_Epetra.H>
#include <NOX_Epetra_MatrixFree.H>

#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdio>
#include <functional>

#include "BreakRounds.hpp"
#include "LoadStepping.hpp"
#include "NoxPairPreconditioner.hpp"
#include "core/Material.hpp"
#include "model/Model.hpp"
#include "parallel/CommunicatorImpl.hpp"

namespace pf {
namespace {

// NOX's view of one load step: x holds the displacements (3 per owned node); F is -(f + b) on free
// dofs and s (x - xbar) on prescribed ones, s the mean preconditioner diagonal so that both kinds of
// rows are alike in scale.
class StepProblem : public NOX::Epetra::Interface::Required, public NOX::Epetra::Interface::Preconditioner {
 public:
  StepProblem(Model& model, double t, std::vector<double> xbar, double scale)
      : model_(model), xbar_(std::move(xbar)), scale_(scale), u_(model.numDofs()), f_(model.numDofs()),
        fResidual_(model.numDofs()), b_(model.numDofs()) {
    model.bodyForce(t, b_.data());
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
    for (int k = 0; k < n; ++k) F[k] = fixed[k] ? scale_ * (x[k] - xbar_[k]) : -(f_[k] + b_[k]);
    if (flag == Residual) {
      fResidual_ = f_;
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
  ResidualNorms norms() const { return residualNorms(model_, fResidual_, b_); }
  const std::string& failure() const { return failure_; }

 private:
  Model& model_;
  std::vector<double> xbar_;
  double scale_;
  std::vector<double> u_, f_, fResidual_, b_;
  std::string failure_;
  std::function<void(const ResidualNorms&)> onResidual_;
};

// The Jacobian of StepProblem's residual, applied matrix-free: -df on free rows, s dx on prescribed ones.
// df is the materials' exact forceDerivative where all have one; otherwise a forward difference of the
// force whose perturbation is scaled to the model's length (1e-7 of the shortest bond): NOX's own
// matrix-free operator scales it by |x|, which is ~0 at the first load step and gives no derivative.
class TangentOperator : public Epetra_Operator, public NOX::Epetra::Interface::Jacobian {
 public:
  TangentOperator(Model& model, const Epetra_Map& map, double scale)
      : model_(model), map_(map), scale_(scale), exact_(model.hasExactTangent()), u_(model.numDofs()),
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
      for (int k = 0; k < n; ++k) Y[col][k] = fixed[k] ? scale_ * du_[k] : -df_[k];
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
  bool exact_;
  std::vector<double> u_;
  mutable std::vector<double> du_, df_, f0_, up_;
};

// Converged when the force residual on free dofs is below the relative tolerance times the load scale
// (the same test ADR uses) or the force-density residual is below the absolute tolerance.
class ForceResidualTest : public NOX::StatusTest::Generic {
 public:
  ForceResidualTest(const StepProblem& p, double rel, double abs) : problem_(p), rel_(rel), abs_(abs) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    if (!solver.getSolutionGroup().isF()) return status_ = NOX::StatusTest::Unevaluated;
    last_ = problem_.norms();
    tol_ = rel_ * last_.load;
    const bool ok = last_.residual <= tol_ || (abs_ > 0 && last_.residualDensity <= abs_) || last_.residual == 0.0;
    return status_ = ok ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override {
    for (int i = 0; i < indent; ++i) os << ' ';
    os << "force residual " << last_.residual << " N (tolerance " << tol_ << " N), density "
       << last_.residualDensity << "\n";
    return os;
  }
  // The factor by which the residual r must still fall to pass (either criterion), 0 if unknown.
  double reductionNeeded(const ResidualNorms& r) const {
    double need = 0;
    if (r.residual > 0) need = std::max(need, rel_ * r.load / r.residual);
    if (abs_ > 0 && r.residualDensity > 0) need = std::max(need, abs_ / r.residualDensity);
    return need;
  }
  const ResidualNorms& last() const { return last_; }
  double tolerance() const { return tol_; }

 private:
  const StepProblem& problem_;
  double rel_, abs_, tol_ = 0;
  ResidualNorms last_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

// The deck's NOX options as NOX reads them.
Teuchos::ParameterList teuchosOf(const ParamTree& tree) {
  Teuchos::ParameterList l;
  for (const ParamTree::Entry& e : tree.entries) {
    switch (e.kind) {
      case ParamTree::Entry::Kind::Double: l.set(e.name, e.number); break;
      case ParamTree::Entry::Kind::Int: l.set(e.name, e.integer); break;
      case ParamTree::Entry::Kind::Bool: l.set(e.name, e.flag); break;
      case ParamTree::Entry::Kind::String: l.set(e.name, e.text); break;
      case ParamTree::Entry::Kind::List: l.set(e.name, teuchosOf(*e.list)); break;
    }
  }
  return l;
}

// Teuchos stores a const char* value as std::string, so string literals work here too.
template <class T>
void setDefault(Teuchos::ParameterList& l, const std::string& name, T v) {
  if (!l.isParameter(name)) l.set(name, v);
}

// NOX's parameters: the deck's, with Periforge's defaults where the deck is silent. *adaptiveTolerance:
// the deck set no Krylov "Tolerance" (each solve then asks for what the force test still needs).
Teuchos::RCP<Teuchos::ParameterList> noxParameters(const NoxOptions& opt, int rank, bool* adaptiveTolerance) {
  auto params = Teuchos::rcp(new Teuchos::ParameterList(teuchosOf(opt.nox)));
  setDefault(*params, "Nonlinear Solver", "Line Search Based");
  Teuchos::ParameterList& print = params->sublist("Printing");
  // Same on every rank: NOX computes the norms it prints collectively and prints on Output Processor.
  setDefault(print, "Output Information",
             opt.verbose ? NOX::Utils::OuterIteration + NOX::Utils::OuterIterationStatusTest + NOX::Utils::Warning
                         : NOX::Utils::Error);
  setDefault(print, "MyPID", rank);
  setDefault(print, "Output Processor", 0);
  Teuchos::ParameterList& dir = params->sublist("Direction");
  setDefault(dir, "Method", "Newton");
  Teuchos::ParameterList& ls = dir.sublist("Newton").sublist("Linear Solver");
  setDefault(ls, "Aztec Solver", "GMRES");
  setDefault(ls, "Max Iterations", 800);
  *adaptiveTolerance = !ls.isParameter("Tolerance");  // a deck's own Tolerance is kept fixed
  setDefault(ls, "Tolerance", 1e-9);
  setDefault(ls, "Size of Krylov Subspace", 200);
  setDefault(ls, "Preconditioner", "ML");
  setDefault(ls, "Preconditioner Reuse Policy", "Reuse");
  setDefault(ls, "Max Age Of Prec", 1000000);
  setDefault(ls, "Output Frequency", 0);
  setDefault(params->sublist("Line Search"), "Method", "Polynomial");
  return params;
}

}  // namespace

struct NoxQuasiStaticSolver::Linear {
  Teuchos::RCP<Epetra_Map> map;        // owned dofs, global id 3 * point + component
  Teuchos::RCP<Epetra_CrsMatrix> M;    // preconditioner matrix (pair stiffness)
  Teuchos::RCP<Epetra_Operator> prec;  // its Ifpack or ML preconditioner, built once for the whole run
};

NoxQuasiStaticSolver::NoxQuasiStaticSolver(NoxOptions o) : opt_(std::move(o)), linear_(std::make_unique<Linear>()) {}

NoxQuasiStaticSolver::~NoxQuasiStaticSolver() = default;

NoxQuasiStaticSolver::Outcome NoxQuasiStaticSolver::newton(Model& model, std::vector<double>& u, double t) {
  const int n = model.numDofs();
  Linear& lin = *linear_;
  if (lin.M.is_null()) {  // the pair stiffness depends on the reference configuration only: build it once
    std::vector<int> dofGids(n);
    for (int i = 0; i < model.numOwned(); ++i)
      for (int a = 0; a < 3; ++a) dofGids[3 * i + a] = 3 * model.layout().gids()[i] + a;
    lin.map = Teuchos::rcp(new Epetra_Map(-1, n, dofGids.data(), 0, model.layout().comm().impl().epetra));
    lin.M = pairMatrix(model, *lin.map, opt_.precBondRadius, &scale_);
  }
  const Epetra_Map& map = *lin.map;
  const double scale = scale_;

  std::vector<double> xbar(u);  // prescribed values were set by the predictor
  auto problem = Teuchos::rcp(new StepProblem(model, t, xbar, scale));
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

  auto tangent = Teuchos::rcp(new TangentOperator(model, map, scale));
  auto linSys = Teuchos::rcp(new NOX::Epetra::LinearSystemAztecOO(print, ls, tangent, tangent, problem, M, noxX0));
  auto group = Teuchos::rcp(new NOX::Epetra::Group(print, problem, noxX0, linSys));

  auto force = Teuchos::rcp(new ForceResidualTest(*problem, opt_.relativeTolerance, opt_.absoluteTolerance));
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

  Outcome out;
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
  out.tolerance = force->tolerance();
  return out;
}

NoxQuasiStaticSolver::Outcome NoxQuasiStaticSolver::advance(Model& model, std::vector<double>& u,
                                                            std::vector<double>& duPrev, double tA, double tB,
                                                            int depth) {
  const bool root = model.layout().rank() == 0;
  const std::vector<double> uA(u);
  predictStep(model, tB, u, duPrev);
  // With damage, Newton solves with the broken set frozen and the breaks are decided at each converged
  // state (BreakRounds.hpp); without, this is one Newton solve.
  Outcome o;
  int iterations = 0, linear = 0;
  o.converged = solveWithBreakRounds(model, u, [&] {
    o = newton(model, u, tB);
    iterations += o.iterations;
    linear += o.linearIterations;
    return o.converged;
  }, tB);
  o.iterations = iterations;
  o.linearIterations = linear;
  if (o.converged) {
    std::vector<double> f(model.numDofs());
    model.internalForce(u.data(), f.data());  // the last residual may have been a perturbed one
    model.commit();
    model.endBreakRounds();
    for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
    return o;
  }
  model.rollback();
  u = uA;
  if (depth < opt_.maxCuts) {
    if (root) std::printf("  Newton did not converge on [%g, %g] (residual %.3e, tolerance %.3e): cutting the step\n",
                          tA, tB, o.residual, o.tolerance);
    const double tm = 0.5 * (tA + tB);
    std::vector<double> half(duPrev);
    for (double& d : half) d *= 0.5;
    Outcome a = advance(model, u, half, tA, tm, depth + 1);
    Outcome b = advance(model, u, half, tm, tB, depth + 1);
    for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
    b.iterations += a.iterations;
    b.linearIterations += a.linearIterations;
    return b;
  }
  if (root) std::printf("  Newton failed on [%g, %g] after %d cuts: falling back to adaptive dynamic relaxation\n", tA,
                        tB, depth);
  predictStep(model, tB, u, duPrev);
  AdrSolver adr(opt_.fallback);
  AdrSolver::StepResult r{};
  solveWithBreakRounds(model, u, [&] {
    r = adr.relax(model, u, tB, uA, step_);  // throws SolverFailure if it fails too
    return true;
  }, tB);
  std::vector<double> f(model.numDofs());
  model.internalForce(u.data(), f.data());
  model.commit();
  model.endBreakRounds();
  for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
  return Outcome{true, r.iterations, 0, r.residual, r.tolerance};
}

void NoxQuasiStaticSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                               const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  step_ = resume ? resume->step : 0;
  runLoadSteps(model, u, v, times, observer,
               [&](std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB) {
                 ++step_;
                 const Outcome o = advance(model, u, duPrev, tA, tB, 0);
                 return StepStats{o.iterations, o.linearIterations, o.residual, o.tolerance};
               },
               resume);
}

}  // namespace pf
