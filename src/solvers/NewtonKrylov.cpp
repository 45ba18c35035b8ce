#include "NewtonKrylov.hpp"

#include <NOX.H>

#include <algorithm>
#include <csignal>
#include <cstdio>

#include "BreakRounds.hpp"
#include "KrylovSolver.hpp"
#include "LoadStepping.hpp"
#include "NoxParameters.hpp"
#include "NoxStepGroup.hpp"
#include "PairStiffness.hpp"
#include "Solver.hpp"
#include "StepEquations.hpp"
#include "core/InputError.hpp"
#include "core/StopSignal.hpp"
#include "model/Model.hpp"

namespace pf {
namespace {

// Converged when the force residual on free dofs is below the relative tolerance times the load scale
// (loadScale, the same test ADR uses) or the force-density residual is below the absolute tolerance.
class ForceResidualTest : public NOX::StatusTest::Generic {
 public:
  ForceResidualTest(const Model& model, const StepResidual& p, double rel, double abs, bool peridigm, double loadFloor)
      : model_(model), problem_(p), rel_(rel), abs_(abs), peridigm_(peridigm), floor_(loadFloor) {}
  // What the absolute tolerance bounds: the force-density norm, or Peridigm's QuasiStatic measure.
  double absoluteMeasure(const ResidualNorms& r) const { return peridigm_ ? r.peridigmQuasiStatic : r.residualDensity; }
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    // SIGTERM/SIGINT end the run between Newton iterations too: a step whose Krylov solves fail may take
    // minutes (every rank checks here, after the same iteration; one reduction).
    const int signal = static_cast<int>(model_.max(static_cast<double>(stopSignal())));
    if (signal != 0)
      throw Interrupted(signal, std::string("stopped by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                                    " during the Newton iterations of a step");
    if (!solver.getSolutionGroup().isF()) return status_ = NOX::StatusTest::Unevaluated;
    last_ = problem_.norms();
    tol_ = rel_ * loadScale(last_, floor_);
    const bool ok = last_.residual <= tol_ || (abs_ > 0 && absoluteMeasure(last_) <= abs_) || last_.residual == 0.0;
    return status_ = ok ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override {
    for (int i = 0; i < indent; ++i) os << ' ';
    os << "force residual " << last_.residual << " N (tolerance " << tol_ << " N), "
       << (peridigm_ ? "Peridigm's |r|_2 + 20 |r|_inf " : "density ") << absoluteMeasure(last_);
    if (abs_ > 0) os << " (tolerance " << abs_ << ")";
    os << "\n";
    return os;
  }
  // The factor by which the residual r must still fall to pass (either criterion), 0 if unknown.
  double reductionNeeded(const ResidualNorms& r) const {
    double need = 0;
    if (r.residual > 0) need = std::max(need, rel_ * loadScale(r, floor_) / r.residual);
    if (abs_ > 0 && absoluteMeasure(r) > 0) need = std::max(need, abs_ / absoluteMeasure(r));
    return need;
  }
  const ResidualNorms& last() const { return last_; }
  double tolerance() const { return tol_; }

 private:
  const Model& model_;
  const StepResidual& problem_;
  double rel_, abs_;
  bool peridigm_;
  double floor_, tol_ = 0;
  ResidualNorms last_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace

void printWork(const Model& model, const NewtonWork& work) {
  if (model.layout().rank() != 0) return;
  std::printf("%s\n", work.summary().c_str());
  std::fflush(stdout);
}

NewtonKrylov::NewtonKrylov(NewtonKrylovOptions o) : opt_(std::move(o)) {}

NewtonKrylov::~NewtonKrylov() = default;

NewtonOutcome NewtonKrylov::solve(Model& model, std::vector<double>& u, double t, const Inertia* inertia,
                                  double loadFloor) {
  // The pair stiffness depends on the reference configuration only (and a Newmark engine's fixed mass
  // term): built once, with its preconditioner, for the engine's life; rebuilding it per step cost more than
  // the Krylov solves.
  const WorkTimer timer(&work_.seconds);
  if (!krylov_)
    krylov_ = std::make_unique<KrylovSolver>(model, opt_.precBondRadius > 0.0 ? opt_.precBondRadius
                                                                              : defaultPreconditionerRadius(model),
                                             inertia ? &inertia->coefficient : nullptr,
                                             opt_.where, &work_);
  // prescribed values were set by the predictor
  StepResidual residual(model, t, u, krylov_->scale(), inertia, &work_);
  StepTangent tangent(model, krylov_->scale(), inertia, opt_.exactJacobian, &work_);
  StepShared shared;
  shared.residual = &residual;
  shared.tangent = &tangent;
  shared.krylov = krylov_.get();
  auto group = Teuchos::rcp(new NoxStepGroup(shared, u));

  bool adaptiveTolerance = false;
  auto params = noxParameters(opt_, model.layout().rank(), &adaptiveTolerance);
  Teuchos::ParameterList& ls = params->sublist("Direction").sublist("Newton").sublist("Linear Solver");

  auto force = Teuchos::rcp(new ForceResidualTest(model, residual, opt_.relativeTolerance, opt_.absoluteTolerance,
                                                      opt_.peridigmAbsolute, loadFloor));
  auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  combo->addStatusTest(force);
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(opt_.maxIterations)));
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));

  // Inexact Newton: each Krylov solve is asked only for a tenth of the reduction the force test still
  // needs, instead of a fixed 1e-9 that over-solves every step whose predictor is already close; Newton
  // stays quadratic while the residual is far from the tolerance (forcing()).
  int evaluations = 0;
  double first = 0;
  if (adaptiveTolerance)
    residual.setOnResidual([&, test = force.get()](const ResidualNorms& r) {
      const double need = test->reductionNeeded(r);
      const double eta = forcing(need, r.residual, evaluations++, first);
      if (need > 0) ls.set("Tolerance", eta);
    });

  NewtonOutcome out;
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  Teuchos::RCP<NOX::Solver::Generic> solver;
  try {
    solver = NOX::Solver::buildSolver(group, combo, params);
  } catch (const std::exception&) {
    // NOX refused an option of a sub-list the deck passes through (the selectors were checked when the deck
    // was read): an input error, not a step that failed to converge.
    throw InputError(opt_.where + ": NOX cannot be set up with the options of its 'Direction' and 'Line Search' "
                                  "sub-lists; check their names and values against NOX's documentation");
  }
  try {
    status = solver->solve();
    out.iterations = solver->getNumIterations();
    work_.newtonIterations += out.iterations;
    if (ls.isSublist("Output"))
      out.linearIterations = ls.sublist("Output").get<int>("Total Number of Linear Iterations", 0);
    dynamic_cast<const NoxStepGroup&>(solver->getSolutionGroup()).copyX(u);
  } catch (const InputError&) {
    throw;  // the deck's linear solver list names something unknown
  } catch (const Interrupted&) {
    throw;  // a stop signal, not a failed step
  } catch (const SolverFailure&) {
    throw;  // the preconditioner cannot be built (KrylovSolver): no step would converge
  } catch (const std::exception&) {
    status = NOX::StatusTest::Failed;
  } catch (...) {  // NOX throws plain strings ("NOX Error") where a direction or line search cannot go on
    status = NOX::StatusTest::Failed;
  }
  out.converged = status == NOX::StatusTest::Converged && force->getStatus() == NOX::StatusTest::Converged;
  keepConvergedForce(out.converged ? residual.lastForceAt(u) : nullptr, u);
  out.residual = force->last().residual;
  out.residualDensity = force->last().residualDensity;
  out.tolerance = force->tolerance();
  out.load = force->last().load;
  out.peridigmResidual = force->last().peridigmQuasiStatic;
  return out;
}

// The Krylov tolerance after the solve's evaluation number k (residual r, the force test's needed reduction
// `need`): a tenth of need; for the first solve of a step with firstSolveForcing, no less than that times the last
// first-iteration contraction (the nonlinear error the Newton step is likely to leave). Keeps that contraction.
double NewtonKrylov::forcing(double need, double r, int k, double& first) {
  double eta = 0.1 * need;
  if (k == 0 && opt_.firstSolveForcing > 0 && contraction_ > 0)
    eta = std::max(eta, opt_.firstSolveForcing * contraction_);
  if (k == 0) first = r;
  if (k == 1 && first > 0) contraction_ = r / first;
  // At most 0.1: a step that starts within a few times its tolerance (an elastic step after a good prediction) needs
  // only that much; 1e-2 asked those solves for 5 GMRES iterations instead of 3 (the paper plate, session 33).
  return std::clamp(eta, 1e-10, 1e-1);
}

void NewtonKrylov::keepConvergedForce(const std::vector<double>* f, const std::vector<double>& u) {
  converged_ = f != nullptr;
  if (!f) return;
  lastModelCall_ = work_.modelCalls();
  convergedU_ = u;
  convergedForce_ = *f;
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
  if (model.hasDamage()) converged_ = false;  // the rounds evaluated the model after the last solve
  return o;
}

}  // namespace pf
