#include "ImplicitDiffusionSolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "Progress.hpp"
#include "ScalarKrylov.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "model/Model.hpp"

namespace pf {

namespace {
const char* const kField = "Temperature";
// Of the Krylov solve of one Newton iteration, relative to its right-hand side: tight, so that one iteration
// meets any Relative Tolerance a deck asks (the operator is linear).
constexpr double kKrylovTolerance = 1e-12;
}  // namespace

SolverEntry ImplicitDiffusionSolver::entry() {
  using S = ParameterSpec;
  SolverEntry e;
  e.name = "ImplicitDiffusion";
  e.doc = "steady heat conduction at each load time (Peridigm's ImplicitDiffusion)";
  e.loadSteps = true;
  e.solves = kField;
  e.parameters = {
      S::integer("Number of Load Steps", "n: load steps from Initial to Final Time").need().atLeast(1),
      S::real("Relative Tolerance", "|L(T)| over the free nodes, relative to the prescribed nodes' |L(T) V| at the "
                                    "step's start (Peridigm's rule)").byDefault("1e-6").positive(),
      S::real("Absolute Tolerance", "|L(T)| over the free nodes [W/m^3]; replaces the relative rule").positive(),
      S::integer("Maximum Solver Iterations", "Newton iterations per load step").byDefault("10").atLeast(1),
      S::text("Belos Linear Solver", "Peridigm's Krylov method; accepted, Periforge's is BiCGStab")
          .oneOf({"BlockCG", "BlockGMRES"}),
      S::integer("Belos Maximum Iterations", "accepted (Peridigm's)").atLeast(1),
      S::real("Belos Relative Tolerance", "accepted (Peridigm's); Periforge solves each iteration to 1e-12").positive(),
      S::flag("Belos Print Status", "accepted (Peridigm's)").byDefault("false"),
      S::text("Time Integration", "Periforge's: `Steady` (Peridigm's: L(T) = 0 at each load time) or `Backward "
                                  "Euler` (transient: rho c (T - T_n) / dt = L(T), dt the load step; needs Density "
                                  "and Specific Heat Capacity in every conducting block)")
          .oneOf({"Steady", "Backward Euler"}).byDefault("Steady"),
      S::flag("Verbose", "print the residual of every iteration").byDefault("false")};
  e.create = [](const ParameterValues& p, const ParamTree&) {
    ImplicitDiffusionOptions o;
    o.relativeTolerance = p.get("Relative Tolerance");
    o.absoluteTolerance = p.get("Absolute Tolerance", 0.0);
    o.maxIterations = static_cast<int>(p.get("Maximum Solver Iterations"));
    o.verbose = p.flag("Verbose");
    o.transient = p.text("Time Integration") == "Backward Euler";
    o.where = p.where();
    return std::unique_ptr<Solver>(new ImplicitDiffusionSolver(o));
  };
  return e;
}

void ImplicitDiffusionSolver::check(const Model& model) const {
  if (!model.hasOperator(kField))
    throw InputError(opt_.where + ": no block conducts heat: give a block a material with conduction (Material Model "
                                  "'Diffusion', or a solid with 'Thermal Conductivity')");
  if (!opt_.transient) return;
  std::vector<double> c(static_cast<std::size_t>(model.numOwned()));
  model.fieldCapacity(kField, c.data());
  double none = 0.0;
  for (double x : c) none = x > 0.0 ? none : 1.0;
  if (model.max(none) > 0.0)
    throw InputError(opt_.where + ": 'Time Integration' = 'Backward Euler' needs 'Density' and 'Specific Heat Capacity' "
                                  "in every block's material (a point without heat capacity)");
}

// One load step from the committed field to time t (the previous load time tPrev): T ends converged, rate = L(T).
// Returns the iterations; sets residual and tol. Throws SolverFailure when the tolerance is not met.
int ImplicitDiffusionSolver::solveStep(Model& model, double tPrev, double t, std::vector<double>& T,
                                      std::vector<double>& rate, double& residual, double& tol) const {
  const int n = model.numOwned();
  StateStore& state = model.state();
  const std::vector<char>& mask = model.fields().prescribedMask(kField);
  const std::vector<double>& V = model.volume();
  auto sum = [&](double x) { return model.sum(x); };
  // Backward Euler: C (T - T_n) / dt = L(T) + s; steady: L(T) + s = 0 (s: the surface conditions at t). R = L(T) + s
  // - C (T - T_n) / dt at the free points.
  const double inertia = opt_.transient ? 1.0 / (t - tPrev) : 0.0;
  std::vector<double> Tn(state.committed(kField), state.committed(kField) + n), C(n), diag(n), inv(n), r(n), b(n), d(n),
      surface(n);
  model.fieldCapacity(kField, C.data());
  model.fieldSurfaceSource(kField, surface.data());  // Heat Flux, Convection's ambient part, at t (applyPrescribed)
  auto residualOf = [&] {
    model.fieldRate(kField, T.data(), rate.data());
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
      r[i] = mask[i] ? 0.0 : rate[i] + surface[i] - inertia * C[i] * (T[i] - Tn[i]);
      s += r[i] * r[i];
    }
    return std::sqrt(sum(s));
  };
  std::copy(Tn.begin(), Tn.end(), state.trial(kField));
  model.updateFields();  // prescribed temperatures of t on the committed field
  std::copy(state.trial(kField), state.trial(kField) + n, T.begin());
  residual = residualOf();
  double reaction = 0.0;  // Peridigm's steady rule: |L(T) V| over the held points at the step's start
  for (int i = 0; i < n; ++i) reaction += mask[i] ? rate[i] * V[i] * rate[i] * V[i] : 0.0;
  const double scale = opt_.transient ? residual : std::sqrt(sum(reaction));
  tol = opt_.absoluteTolerance > 0.0 ? opt_.absoluteTolerance : opt_.relativeTolerance * scale;
  model.fieldDiagonal(kField, diag.data());
  for (int i = 0; i < n; ++i) {
    const double jii = diag[i] + inertia * C[i];  // |dR_i / dT_i|
    inv[i] = mask[i] || !(jii > 0.0) ? 1.0 : -1.0 / jii;
  }
  // dR/dT on a correction that is 0 at the held points: L(x) - C x / dt at the free ones, x itself at those.
  auto apply = [&](const double* x, double* y) {
    model.fieldRate(kField, x, y);
    for (int i = 0; i < n; ++i) y[i] = mask[i] ? x[i] : y[i] - inertia * C[i] * x[i];
  };
  int iterations = 0;
  while (residual > tol && iterations < opt_.maxIterations) {
    for (int i = 0; i < n; ++i) b[i] = -r[i];
    // An unconverged Krylov solve still improves T; the Newton loop's residual test decides.
    bicgstab(apply, inv, b, d, kKrylovTolerance, 10 * model.layout().numGlobal() + 100, sum);
    for (int i = 0; i < n; ++i) T[i] += mask[i] ? 0.0 : d[i];
    residual = residualOf();
    ++iterations;
    if (model.layout().rank() == 0 && opt_.verbose)
      std::printf("  iteration %d: residual %.6e (tolerance %.3e)\n", iterations, residual, tol);
  }
  if (!std::isfinite(residual) || residual > tol) {
    char msg[200];
    std::snprintf(msg, sizeof msg, ": load step to t = %g: residual %.6e above the tolerance %.6e after %d iterations", t,
                  residual, tol, iterations);
    throw SolverFailure(opt_.where + msg);
  }
  return iterations;
}

void ImplicitDiffusionSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                                  const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  const int n = model.numOwned();
  model.fields().setSolved(kField);
  StateStore& state = model.state();
  std::vector<double> T(n), rate(n, 0.0), f(u.size(), 0.0);
  auto report = [&](int step, double t, int iterations, double residual, double tol, double wall) {
    StepReport r{step, t, iterations, residual, tol, wall, nullptr};
    r.nonlinearIterations = iterations;  // Peridigm's ImplicitDiffusion counts each Newton iteration
    observer.onStep(r, u, v, f);
  };
  std::size_t k = 1;
  if (resume) {
    k = static_cast<std::size_t>(resume->step) + 1;
    model.applyPrescribed(resume->time, u.data());
  } else {
    model.applyPrescribed(times.front(), u.data());
    model.updateFields();  // the start: initial and prescribed temperatures of t0, Flux_Divergence 0 (Peridigm's)
    report(0, times.front(), 0, 0.0, 0.0, 0.0);
  }
  const ProgressClock progress(static_cast<long>(k), static_cast<long>(times.size()) - 1);
  for (; k < times.size(); ++k) {
    const auto clock = std::chrono::steady_clock::now();
    const double t = times[k];
    model.applyPrescribed(t, u.data());
    double residual = 0.0, tol = 0.0;
    const int iterations = solveStep(model, times[k - 1], t, T, rate, residual, tol);
    std::copy(T.begin(), T.end(), state.trial(kField));
    model.updateFields();  // the change and the ghosts of the solved field
    std::copy(rate.begin(), rate.end(), state.trial("Flux_Divergence"));
    model.commit();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    if (model.layout().rank() == 0)
      std::printf("load step %4zu/%zu  t = %-10g Newton iterations %3d  residual %.3e (tol %.3e)  wall %.2f s%s\n", k,
                  times.size() - 1, t, iterations, residual, tol, wall, progress.leftAfter(static_cast<long>(k)).c_str());
    report(static_cast<int>(k), t, iterations, residual, tol, wall);
  }
}

}  // namespace pf
