#include "AdrSolver.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>

#include "BreakRounds.hpp"
#include "FiniteCheck.hpp"
#include "LoadStepping.hpp"
#include "YieldRounds.hpp"
#include "core/InputError.hpp"
#include "core/StopSignal.hpp"
#include "model/Model.hpp"

namespace pf {

SolverEntry AdrSolver::entry() {
  using S = ParameterSpec;
  SolverEntry e;
  e.name = "Adaptive Dynamic Relaxation";
  e.doc = "quasi-static load steps by adaptive dynamic relaxation (Kilic & Madenci 2010)";
  e.loadSteps = true;
  e.parameters = {
      S::integer("Number of Load Steps", "n: load steps from Initial to Final Time").need().atLeast(1),
      S::real("Relative Tolerance", "residual / load scale (reaction + body force, never below the largest of a converged step) that ends a step; at least 1e-14 (below, a converged step's residual is round-off)").byDefault("1e-6").atLeast(1e-14),
      S::real("Absolute Tolerance", "residual force-density norm that also ends a step (default: none)").positive(),
      S::integer("Maximum Iterations", "per load step; then the run fails").byDefault("100000").atLeast(1),
      S::real("Safety Factor", "multiplies the fictitious density").byDefault("1").positive(),
      S::flag("Verbose", "print the residual history of every step").byDefault("false"),
      S::flag("Loading Balance Correction",
              "Li & Geng's loading-balance correction: relax with the step's admitted plastic set frozen (empty at "
              "the start: all elastic), admit the points past their yield surface, relax again until none is; "
              "then commit (materials that support it: Drucker Prager Correspondence)").byDefault("false"),
      S::real("Loading Balance Tolerance",
              "the material's dimensionless yield function (Drucker-Prager: J / J_yield - 1) above which a point "
              "outside the admitted set is admitted; default: ADR's default Relative Tolerance").byDefault("1e-6")
          .nonNegative(),
      S::text("Loading Balance Start",
              "the admitted set at the start of a step: Elastic (empty, the paper's) or Yield Surface (the points on "
              "their yield surface at the last commit, i.e. those that flowed in the last step)")
          .oneOf({"Elastic", "Yield Surface"}).byDefault("Elastic")};
  e.create = [](const ParameterValues& p, const ParamTree&) {
    AdrOptions o;
    o.relativeTolerance = p.get("Relative Tolerance");
    o.absoluteTolerance = p.get("Absolute Tolerance", 0.0);
    o.maxIterations = static_cast<int>(p.get("Maximum Iterations"));
    o.safetyFactor = p.get("Safety Factor");
    o.verbose = p.flag("Verbose");
    o.loadBalance = p.flag("Loading Balance Correction");
    o.loadBalanceTolerance = p.get("Loading Balance Tolerance");
    o.loadBalanceFromSurface = p.text("Loading Balance Start") == "Yield Surface";
    o.where = p.where();
    return std::unique_ptr<Solver>(new AdrSolver(o));
  };
  return e;
}

namespace {

// A NaN residual never converges: stop at once (naming the node) instead of iterating to the limit.
// The norms are reduced already, so every rank takes the same branch.
void requireFiniteResidual(Model& model, const ResidualNorms& nr, long step, double t, const std::vector<double>& f,
                           const std::vector<double>& b) {
  if (std::isfinite(nr.residual) && std::isfinite(nr.load)) return;
  const std::vector<char>& fixed = model.prescribedMask();
  std::vector<double> r(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) r[k] = fixed[k] ? f[k] : f[k] + b[k];
  model.rollback();
  requireFinite(model, CheckPoint{"adaptive dynamic relaxation", step, t}, "residual", r, finiteProbe(r));
  requireFinite(model, CheckPoint{"adaptive dynamic relaxation", step, t}, "residual", r, NAN);  // norm overflow
}

// A load step may take 10^5 iterations (minutes): SIGTERM/SIGINT are polled every kSignalPoll iterations, all
// ranks agreeing (one reduction), and stop the run inside the step, the step's state rolled back; the output
// files keep the converged steps (docs/output.md).
constexpr int kSignalPoll = 500;
// How often a long relaxation prints its progress (rank 0, when `Verbose` does not print every iteration).
constexpr std::chrono::seconds kProgressEvery{30};

void stopIfSignalled(Model& model, double t) {
  const int signal = static_cast<int>(model.max(static_cast<double>(stopSignal())));
  if (signal == 0) return;
  model.rollback();
  char what[160];
  std::snprintf(what, sizeof what, "stopped by %s during the load step to t = %g", signal == SIGINT ? "SIGINT" : "SIGTERM", t);
  throw Interrupted(signal, what);
}

}  // namespace

AdrSolver::StepResult AdrSolver::relax(Model& model, std::vector<double>& u, double t,
                                       const std::vector<double>& uStart, long step, double loadFloor) const {
  const int n = model.numDofs();
  const bool root = model.layout().rank() == 0;
  const std::vector<char>& fixed = model.prescribedMask();
  // Fictitious density lambda_ii = dt^2/4 sum_j |K_ij| with pseudo time step dt = 1 (Kilic & Madenci Eq. 17).
  std::vector<double> lambda(n);
  for (int k = 0; k < n; ++k) lambda[k] = 0.25 * opt_.safetyFactor * model.stiffnessBound()[k / 3];
  std::vector<double> f(n), b(n), r(n), rOld(n), v(n, 0.0);
  model.bodyForce(t, b.data());
  atStep(CheckPoint{"adaptive dynamic relaxation", step, t}, [&] { model.internalForce(u.data(), f.data()); });
  ResidualNorms nr = residualNorms(model, f, b);
  requireFiniteResidual(model, nr, step, t, f, b);
  double tol = 0;
  int it = 0;
  // A step that relaxes for long (a Newton fallback at a fine resolution can take hours) reports where it is.
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  Clock::time_point reported = started;
  for (;; ++it) {
    tol = opt_.relativeTolerance * loadScale(nr, loadFloor);
    const bool absOk = opt_.absoluteTolerance > 0 && nr.residualDensity <= opt_.absoluteTolerance;
    if (nr.residual <= tol || absOk || nr.residual == 0.0) break;
    if (it >= opt_.maxIterations) {
      model.rollback();
      char msg[256];
      std::snprintf(msg, sizeof msg,
                    "adaptive dynamic relaxation: load step at t = %g did not converge in %d iterations "
                    "(residual %.3e N, tolerance %.3e N)", t, it, nr.residual, tol);
      throw SolverFailure(msg);
    }
    for (int k = 0; k < n; ++k) r[k] = fixed[k] ? 0.0 : f[k] + b[k];
    // Damping from the local Rayleigh quotient du^T K du / du^T du with the diagonal K_ii estimated from
    // the change of residual over the last pseudo step (Kilic & Madenci Eqs. 19-20).
    double c = 0.0;
    if (it > 0) {
      double loc[2] = {0, 0}, glob[2];
      for (int k = 0; k < n; ++k) {
        if (fixed[k] || v[k] == 0.0) continue;
        const double kii = -(r[k] - rOld[k]) / (lambda[k] * v[k]);
        const double du = u[k] - uStart[k];
        loc[0] += du * kii * du;
        loc[1] += du * du;
      }
      model.layout().comm().sum(loc, glob, 2);
      if (glob[0] > 0 && glob[1] > 0) c = std::min(2.0 * std::sqrt(glob[0] / glob[1]), 1.999);
      for (int k = 0; k < n; ++k) v[k] = ((2.0 - c) * v[k] + 2.0 * r[k] / lambda[k]) / (2.0 + c);
    } else {
      for (int k = 0; k < n; ++k) v[k] = 0.5 * r[k] / lambda[k];
    }
    for (int k = 0; k < n; ++k) u[k] += v[k];
    rOld = r;
    atStep(CheckPoint{"adaptive dynamic relaxation", step, t}, [&] { model.internalForce(u.data(), f.data()); });
    nr = residualNorms(model, f, b);
    requireFiniteResidual(model, nr, step, t, f, b);
    if (opt_.verbose && root) std::printf("  ADR it %d  residual %.6e  damping %.4f\n", it + 1, nr.residual, c);
    if (root && !opt_.verbose && Clock::now() - reported > kProgressEvery) {
      reported = Clock::now();
      std::printf("  relaxing to t = %g: iteration %d of at most %d, residual %.3e N (tolerance %.3e N), %.0f s\n", t,
                  it + 1, opt_.maxIterations, nr.residual, tol,
                  std::chrono::duration<double>(reported - started).count());
      std::fflush(stdout);
    }
    if ((it + 1) % kSignalPoll == 0) stopIfSignalled(model, t);
  }
  return {it, nr.residual, tol, nr.load};
}

void AdrSolver::check(const Model& model) const {
  if (!opt_.loadBalance) return;
  const std::string refusal = model.yieldRoundsRefusal();
  if (!refusal.empty())
    throw InputError(opt_.where + ": 'Loading Balance Correction' = true: " + refusal +
                     " does not support it (it needs a model that can hold a point elastic: Drucker Prager "
                     "Correspondence)");
}

void AdrSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
                    StepObserver& observer) {
  const SolverResume* resume = takeResume();
  long step = resume ? resume->step : 0;  // for messages
  runLoadSteps(model, u, v, times, observer,
               [&](std::vector<double>& u, std::vector<double>& duPrev, double, double t, double loadFloor) {
                 const std::vector<double> uStepStart(u);
                 predictStep(model, t, u, duPrev);
                 // relax's last force evaluation was at the converged u, so the trial state is that of u
                 // (with damage, the break rounds' last evaluation at u: BreakRounds.hpp)
                 // (and with the loading-balance correction, the last round's: YieldRounds.hpp)
                 StepResult r{};
                 int iterations = 0, rounds = 0;
                 ++step;
                 auto relaxOnce = [&] {
                   r = relax(model, u, t, uStepStart, step, loadFloor);
                   iterations += r.iterations;
                 };
                 solveWithBreakRounds(model, u, [&] {
                   if (!opt_.loadBalance) relaxOnce();
                   else rounds += solveWithYieldRounds(model, relaxOnce, t, opt_.loadBalanceTolerance, opt_.loadBalanceFromSurface);
                   return true;
                 }, t);
                 model.commit();
                 model.endBreakRounds();
                 model.endYieldRounds();
                 for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uStepStart[k];
                 StepStats s{iterations, -1, r.residual, r.tolerance, r.load};
                 s.rounds = opt_.loadBalance ? rounds : -1;
                 return s;
               },
               resume);
}

}  // namespace pf
