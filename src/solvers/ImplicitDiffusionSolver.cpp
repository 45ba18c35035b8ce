#include "ImplicitDiffusionSolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "Progress.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "model/Model.hpp"

namespace pf {

namespace {
const char* const kField = "Temperature";
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
    ImplicitFieldOptions o;
    o.relativeTolerance = p.get("Relative Tolerance");
    o.absoluteTolerance = p.get("Absolute Tolerance", 0.0);
    o.maxIterations = static_cast<int>(p.get("Maximum Solver Iterations"));
    o.verbose = p.flag("Verbose");
    o.transient = p.text("Time Integration") == "Backward Euler";
    o.where = p.where();
    o.transientBy = "'Time Integration' = 'Backward Euler'";
    return std::unique_ptr<Solver>(new ImplicitDiffusionSolver(o));
  };
  return e;
}

void ImplicitDiffusionSolver::check(const Model& model) const { ImplicitFieldStep(model, kField, opt_); }

void ImplicitDiffusionSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                                  const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  model.fields().setSolved(kField);
  ImplicitFieldStep heat(model, kField, opt_);
  std::vector<double> f(u.size(), 0.0);
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
    const ImplicitFieldStep::Outcome o = heat.advance(model, times[k - 1], t, false);
    const int iterations = o.iterations;
    const double residual = o.residual, tol = o.tolerance;
    model.commit();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    if (model.layout().rank() == 0)
      std::printf("load step %4zu/%zu  t = %-10g Newton iterations %3d  residual %.3e (tol %.3e)  wall %.2f s%s\n", k,
                  times.size() - 1, t, iterations, residual, tol, wall, progress.leftAfter(static_cast<long>(k)).c_str());
    report(static_cast<int>(k), t, iterations, residual, tol, wall);
  }
}

}  // namespace pf
