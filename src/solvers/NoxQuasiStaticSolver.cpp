#include "NoxQuasiStaticSolver.hpp"

#include <algorithm>
#include <cstdio>

#include "BreakRounds.hpp"
#include "LoadStepping.hpp"
#include "core/InputError.hpp"
#include "model/Model.hpp"

namespace pf {

NoxQuasiStaticSolver::NoxQuasiStaticSolver(NoxOptions o) : opt_(std::move(o)), newton_(opt_.newton) {}

NoxQuasiStaticSolver::~NoxQuasiStaticSolver() = default;

namespace {

// A step's residual and bound in the measure the deck set, for its messages: Peridigm's ||r||_2 + 20 ||r||_inf against
// its Absolute Tolerance for Peridigm's QuasiStatic with one, else the force residual against the relative bound (0
// when the deck gives only an absolute tolerance: printing it said "tolerance 0").
struct DeckMeasure {
  double residual, tolerance;
  bool peridigm;  // Peridigm's measure against its Absolute Tolerance
};
DeckMeasure deckMeasure(const NewtonKrylovOptions& newton, const NewtonOutcome& o) {
  if (newton.peridigmAbsolute && newton.absoluteTolerance > 0.0)
    return {o.peridigmResidual, newton.absoluteTolerance, true};
  return {o.residual, o.tolerance, false};
}

}  // namespace

ImplicitFieldOptions NoxQuasiStaticSolver::heatOptions() const {
  ImplicitFieldOptions o;
  // The heat equation is linear in T: one Newton iteration (a Krylov solve to 1e-12) meets this.
  o.relativeTolerance = kHeatRelativeTolerance;
  o.transient = true;
  o.where = opt_.newton.where;
  o.transientBy = "'Solve For Temperature' = true";
  return o;
}

void NoxQuasiStaticSolver::check(const Model& model) const {
  if (advances("Temperature")) ImplicitFieldStep(model, "Temperature", heatOptions());
}

void NoxQuasiStaticSolver::startHeat(Model& model) {
  if (!advances("Temperature")) return;
  model.fields().setSolved("Temperature");
  heat_ = std::make_unique<ImplicitFieldStep>(model, "Temperature", heatOptions());
}

// The model's state is committed from a last force pass at u: the Newton solve's last residual when the model has
// not been called since (NewtonKrylov::convergedForce; a product or a break round may have come after it), else a new
// one. The heat step reads that pass's trial state (plastic heating); the break rounds end; duPrev = the step's
// increment.
void NoxQuasiStaticSolver::commitStep(Model& model, const std::vector<double>& u, const std::vector<double>& uA,
                                      std::vector<double>& duPrev, double tA, double tB) {
  std::vector<double>& f = committedForce_;
  f.resize(static_cast<std::size_t>(model.numDofs()));
  if (const std::vector<double>* known = newton_.convergedForce(u))
    f = *known;
  else
    model.internalForce(u.data(), f.data());
  if (heat_) heat_->advance(model, tA, tB, true);
  model.commit();
  model.endBreakRounds();
  for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
}

NoxQuasiStaticSolver::Outcome NoxQuasiStaticSolver::advance(Model& model, std::vector<double>& u,
                                                            std::vector<double>& duPrev, double tA, double tB,
                                                            int depth, double loadFloor) {
  const bool root = model.layout().rank() == 0;
  const std::vector<double> uA(u);
  predictStep(model, tB, u, duPrev, opt_.quadraticPredictor ? &solved_ : nullptr);
  // With damage, Newton solves with the broken set frozen and the breaks are decided at each converged
  // state (BreakRounds.hpp); without, this is one Newton solve.
  Outcome o = newton_.solveWithBreaks(model, u, tB, nullptr, loadFloor);
  if (o.converged) {
    commitStep(model, u, uA, duPrev, tA, tB);
    if (opt_.quadraticPredictor && o.iterations > 0) solved_.record(u);
    return o;
  }
  model.rollback();
  u = uA;
  const DeckMeasure m = deckMeasure(opt_.newton, o);
  if (depth < opt_.maxCuts) {
    if (root) std::printf("  Newton did not converge on [%g, %g] (residual %.3e, tolerance %.3e): cutting the step\n",
                          tA, tB, m.residual, m.tolerance);
    std::fflush(stdout);
    const double tm = 0.5 * (tA + tB);
    std::vector<double> half(duPrev);
    for (double& d : half) d *= 0.5;
    Outcome a = advance(model, u, half, tA, tm, depth + 1, loadFloor);
    Outcome b = advance(model, u, half, tm, tB, depth + 1, std::max(loadFloor, a.load));
    for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
    b.iterations += a.iterations;
    b.linearIterations += a.linearIterations;
    return b;
  }
  if (root) std::printf("  Newton failed on [%g, %g] after %d cuts: falling back to adaptive dynamic relaxation\n", tA,
                        tB, depth);
  std::fflush(stdout);
  predictStep(model, tB, u, duPrev);
  AdrSolver adr(opt_.fallback);
  AdrSolver::StepResult r{};
  solveWithBreakRounds(model, u, [&] {
    r = adr.relax(model, u, tB, uA, step_, loadFloor);  // throws SolverFailure if it fails too
    return true;
  }, tB);
  commitStep(model, u, uA, duPrev, tA, tB);
  if (opt_.quadraticPredictor) solved_.record(u);
  return Outcome{true, r.iterations, 0, r.residual, r.tolerance, 0.0, r.load};
}

void NoxQuasiStaticSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                               const std::vector<double>& times, StepObserver& observer) {
  startHeat(model);
  if (opt_.adaptive.on) return runAdaptive(model, u, v, times, observer);
  const SolverResume* resume = takeResume();
  step_ = resume ? resume->step : 0;
  CarriedState own;  // what the next step's predictor and Krylov forcing read
  if (opt_.quadraticPredictor) solved_.carriedBy(own);
  if (opt_.newton.firstSolveForcing > 0)
    own.scalars.push_back({"First Solve Contraction", &newton_.firstIterationContraction()});
  runLoadSteps(model, u, v, times, observer,
               [&](std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB, double loadFloor) {
                 ++step_;
                 const Outcome o = advance(model, u, duPrev, tA, tB, 0, loadFloor);
                 StepStats s{o.iterations, o.linearIterations, o.residual, o.tolerance, o.load};
                 // Peridigm counts each NOX step() call, one even when the step starts converged (NOX then
                 // iterates 0 times), and its own QuasiStatic Newton each iteration (Peridigm.cpp).
                 s.nonlinearIterations = opt_.newton.peridigmAbsolute ? o.iterations : std::max(1, o.iterations);
                 // The committed pass's force is the step's (a new pass after the commit would redo it from the
                 // committed state, the same to round-off, for another force evaluation per step).
                 s.force = &committedForce_;
                 return s;
               },
               resume, &own);
  printWork(model, newton_.work());
  printHeatWork(model);
}

void NoxQuasiStaticSolver::printHeatWork(const Model& model) const {
  if (heat_ && model.layout().rank() == 0)
    std::printf("NOXQuasiStatic: Temperature by Backward Euler after each step: %ld Newton iterations\n",
                heat_->iterationsTaken());
}

namespace {

// The explicit run after the switch writes at the `Switch to Verlet` list's Output Frequency (Peridigm's output
// counter goes on across the switch: the explicit run's initial state is counted, so with frequency 10 it writes
// its steps 9, 19, ...).
class ExplicitCadence : public StepObserver {
 public:
  ExplicitCadence(StepObserver& next, int every) : next_(next), every_(every) {}
  void onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
              const std::vector<double>& f) override {
    StepReport r = report;
    r.outputEvery = every_;
    next_.onStep(r, u, v, f);
  }

 private:
  StepObserver& next_;
  int every_;
};

}  // namespace

void NoxQuasiStaticSolver::runAdaptive(Model& model, std::vector<double>& u, std::vector<double>& v,
                                       const std::vector<double>& given, StepObserver& observer) {
  const AdaptiveLoadStepping& a = opt_.adaptive;
  if (takeResume())
    throw InputError(opt_.newton.where + ": a restart of a run with 'Adaptive Load-Stepping' is not supported");
  const bool root = model.layout().rank() == 0;
  std::vector<double> times(given);
  int inStep = 0, total = 0, outputFactor = 1;
  double switchAt = -1.0;  // >= 0: the explicit run starts there
  step_ = 0;
  runLoadSteps(model, u, v, times, observer,
               [&](std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB, double loadFloor) {
                 ++step_;
                 const std::vector<double> uA(u);
                 predictStep(model, tB, u, duPrev);
                 Outcome o = newton_.solveWithBreaks(model, u, tB, nullptr, loadFloor);
                 const DeckMeasure m = deckMeasure(opt_.newton, o);
                 const double tol = m.tolerance, res = m.residual;
                 // Peridigm accepts a step whose residual ends within 100 times its tolerance, with a warning.
                 if (!o.converged && m.peridigm && res < 100.0 * tol) {
                   if (root) std::printf("  step to t = %g accepted at residual %.3e (tolerance %.3e), as Peridigm\n",
                                         tB, res, tol);
                   o.converged = true;
                 }
                 StepStats s{o.iterations, o.linearIterations, o.residual, o.tolerance, o.load};
                 s.nonlinearIterations = o.iterations;
                 if (o.converged) {
                   commitStep(model, u, uA, duPrev, tA, tB);
                   inStep = 0;
                   s.outputEveryFactor = outputFactor;
                   s.force = &committedForce_;
                   return s;
                 }
                 model.rollback();
                 u = uA;
                 ++inStep;
                 ++total;
                 if (inStep > a.maxReductionsInStep || total > a.maxTotalReductions) {
                   if (!a.switchToVerlet) {
                     char msg[256];
                     std::snprintf(msg, sizeof msg, "QuasiStatic step to t = %g did not converge (residual %.3e, "
                                   "tolerance %.3e) after %d load step reductions (%d in all)", tB, res, tol,
                                   inStep - 1, total - 1);
                     throw SolverFailure(msg);
                   }
                   switchAt = tA;
                   s.outcome = StepStats::Outcome::Stop;
                   return s;
                 }
                 const double half = halveStep(times, tA, tB, a.reduceRemaining);
                 if (a.adaptiveOutput) outputFactor *= 2;
                 if (root) std::printf("  QuasiStatic step to t = %g did not converge (residual %.3e, tolerance %.3e): "
                                       "load step reduced to %g\n", tB, res, tol, half);
                 for (double& d : duPrev) d *= 0.5;
                 s.outcome = StepStats::Outcome::Retry;
                 return s;
               },
               nullptr);
  printWork(model, newton_.work());
  printHeatWork(model);
  if (switchAt < 0.0) return;
  if (root) std::printf("periforge: QuasiStatic: switching to Verlet at t = %g (Adaptive Load-Stepping)\n", switchAt);
  VerletSolver verlet(a.verlet);
  verlet.setFields(advances("Temperature") ? std::vector<std::string>{"Displacement", "Temperature"}
                                            : std::vector<std::string>{"Displacement"});
  verlet.check(model);
  ExplicitCadence cadence(observer, a.verletOutputFrequency);
  verlet.run(model, u, v, {switchAt, given.back()}, cadence);
}

}  // namespace pf
