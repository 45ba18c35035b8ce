#include "ImplicitDiffusionSolver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

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
      S::flag("Verbose", "print the residual of every iteration").byDefault("false")};
  e.create = [](const ParameterValues& p, const ParamTree&) {
    ImplicitDiffusionOptions o;
    o.relativeTolerance = p.get("Relative Tolerance");
    o.absoluteTolerance = p.get("Absolute Tolerance", 0.0);
    o.maxIterations = static_cast<int>(p.get("Maximum Solver Iterations"));
    o.verbose = p.flag("Verbose");
    o.where = p.where();
    return std::unique_ptr<Solver>(new ImplicitDiffusionSolver(o));
  };
  return e;
}

void ImplicitDiffusionSolver::check(const Model& model) const {
  if (!model.hasOperator(kField))
    throw InputError(opt_.where + ": no block conducts heat: give a block a material with conduction (Material Model "
                                  "'Diffusion')");
}

void ImplicitDiffusionSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                                  const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  const int n = model.numOwned();
  model.fields().setSolved(kField);
  StateStore& state = model.state();
  const std::vector<char>& mask = model.fields().prescribedMask(kField);
  const std::vector<double>& V = model.volume();
  std::vector<double> T(n), rate(n, 0.0), diag(n), inv(n), b(n), d(n), f(u.size(), 0.0);
  auto sum = [&](double x) { return model.sum(x); };
  auto freeNorm = [&](const std::vector<double>& r) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += mask[i] ? 0.0 : r[i] * r[i];
    return std::sqrt(sum(s));
  };
  auto report = [&](int step, double t, int iterations, double residual, double tol, double wall) {
    StepReport r{step, t, iterations, residual, tol, wall, nullptr};
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
  for (; k < times.size(); ++k) {
    const auto clock = std::chrono::steady_clock::now();
    const double t = times[k];
    model.applyPrescribed(t, u.data());
    std::copy(state.committed(kField), state.committed(kField) + n, state.trial(kField));
    model.updateFields();  // prescribed temperatures of t on the committed field
    std::copy(state.trial(kField), state.trial(kField) + n, T.begin());
    model.fieldRate(kField, T.data(), rate.data());
    double reaction = 0.0;
    for (int i = 0; i < n; ++i) reaction += mask[i] ? rate[i] * V[i] * rate[i] * V[i] : 0.0;
    const double tol = opt_.absoluteTolerance > 0.0 ? opt_.absoluteTolerance : opt_.relativeTolerance * std::sqrt(sum(reaction));
    model.fieldDiagonal(kField, diag.data());
    for (int i = 0; i < n; ++i) inv[i] = mask[i] || !(diag[i] > 0.0) ? 1.0 : -1.0 / diag[i];
    double residual = freeNorm(rate);
    int iterations = 0;
    // The operator on a correction d that is 0 at the prescribed nodes: L(d) at the free ones, d itself at those.
    auto apply = [&](const double* x, double* y) {
      model.fieldRate(kField, x, y);
      for (int i = 0; i < n; ++i)
        if (mask[i]) y[i] = x[i];
    };
    while (residual > tol && iterations < opt_.maxIterations) {
      for (int i = 0; i < n; ++i) b[i] = mask[i] ? 0.0 : -rate[i];
      // An unconverged Krylov solve still improves T; the Newton loop's residual test decides.
      bicgstab(apply, inv, b, d, kKrylovTolerance, 10 * model.layout().numGlobal() + 100, sum);
      for (int i = 0; i < n; ++i) T[i] += mask[i] ? 0.0 : d[i];
      model.fieldRate(kField, T.data(), rate.data());
      residual = freeNorm(rate);
      ++iterations;
      if (model.layout().rank() == 0 && opt_.verbose)
        std::printf("  iteration %d: residual %.6e (tolerance %.3e)\n", iterations, residual, tol);
    }
    if (!std::isfinite(residual) || residual > tol) {
      char msg[200];
      std::snprintf(msg, sizeof msg, ": load step %zu (t = %g): residual %.6e above the tolerance %.6e after %d iterations",
                    k, t, residual, tol, iterations);
      throw SolverFailure(opt_.where + msg);
    }
    std::copy(T.begin(), T.end(), state.trial(kField));
    model.updateFields();  // the change and the ghosts of the solved field
    std::copy(rate.begin(), rate.end(), state.trial("Flux_Divergence"));
    model.commit();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    if (model.layout().rank() == 0)
      std::printf("load step %4zu/%zu  t = %-10g Newton iterations %3d  residual %.3e (tol %.3e)  wall %.2f s\n", k,
                  times.size() - 1, t, iterations, residual, tol, wall);
    report(static_cast<int>(k), t, iterations, residual, tol, wall);
  }
}

}  // namespace pf
