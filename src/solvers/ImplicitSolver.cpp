#include "ImplicitSolver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "FiniteCheck.hpp"
#include "Progress.hpp"
#include "VerletSolver.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "model/Model.hpp"

namespace pf {

SolverEntry ImplicitSolver::entry() {
  using S = ParameterSpec;
  SolverEntry e;
  e.name = "Implicit";
  e.doc = "Peridigm's implicit dynamics: Newmark-beta with a fixed time step, Newton-Krylov per step";
  e.dynamic = true;
  ParameterSpec beta = S::real("Beta", "Newmark's β; ¼ (with `Gamma` ½): the trapezoidal rule, unconditionally stable; "
                                       "below `Gamma`/2 stable for ω dt ≤ 1/√(γ/2 − β), ω bounded by the model's highest "
                                       "frequency estimate: a warning, above twice that limit an input error")
                           .byDefault("0.25").positive();
  beta.max = 0.5;  // beyond 1/2 the scheme is no longer second order nor Peridigm's; (0, 1/2]
  e.parameters = {
      S::real("Fixed dt", "time step; the run takes floor((Final Time − Initial Time) / dt) steps, as Peridigm")
          .need().positive(),
      beta,
      S::real("Gamma", "Newmark's γ; ½: no numerical damping; above: damping (first order); below ½ the "
                       "scheme amplifies and is refused").byDefault("0.5").atLeast(0.5),
      S::real("Absolute Tolerance", "a step converges when β dt² ‖ρa − f − b‖₂ over the free dofs (Peridigm's "
                                    "residual, kg/m²) is at most this").byDefault("1e-6").positive(),
      S::integer("Maximum Solver Iterations", "Newton iterations per time step; a step still above the "
                                              "tolerance stops the run").byDefault("10").atLeast(1),
      S::text("Initial Acceleration",
              "the acceleration the first step starts from: Zero (Peridigm's: its loop never evaluates the initial "
              "equation of motion) or Equation of Motion ((f + b)/ρ of the initial state, Newmark's consistent start; "
              "they differ when the initial state carries a force: an initial displacement, a body force)")
          .oneOf({"Zero", "Equation of Motion"}).byDefault("Zero"),
      S::flag("Verbose", "print NOX's residual history").byDefault("false")};
  e.create = [](const ParameterValues& p, const ParamTree&) {
    ImplicitOptions o;
    o.dt = p.get("Fixed dt");
    o.beta = p.get("Beta");
    o.gamma = p.get("Gamma");
    o.absoluteTolerance = p.get("Absolute Tolerance");
    o.newton.maxIterations = static_cast<int>(p.get("Maximum Solver Iterations"));
    o.newton.verbose = p.flag("Verbose");
    o.initialEquationOfMotion = p.text("Initial Acceleration") == "Equation of Motion";
    o.where = p.where();
    o.newton.where = o.where;
    return std::unique_ptr<Solver>(new ImplicitSolver(o));
  };
  return e;
}

ImplicitSolver::ImplicitSolver(ImplicitOptions o) : opt_(std::move(o)) {
  // Peridigm's residual is beta dt^2 (rho a - f - b); the engine tests the force density |f + b - rho a|.
  opt_.newton.relativeTolerance = 0.0;
  opt_.newton.absoluteTolerance = opt_.absoluteTolerance / (opt_.beta * opt_.dt * opt_.dt);
}

long ImplicitSolver::stepCount(double t0, double t1, double dt) {
  return static_cast<long>(std::floor((t1 - t0) / dt * (1.0 + 1e-12)));
}

namespace {

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

// The state a step starts from and its Newmark predictor, per dof.
struct Newmark {
  double dt, beta, gamma;
  // u~ = u + dt v + dt^2 (1/2 - beta) a and v~ = v + dt (1 - gamma) a: the step's known part.
  void predict(const std::vector<double>& u, const std::vector<double>& v, const std::vector<double>& a,
               std::vector<double>& uTilde, std::vector<double>& vTilde) const {
    for (std::size_t k = 0; k < u.size(); ++k) {
      uTilde[k] = u[k] + dt * v[k] + dt * dt * (0.5 - beta) * a[k];
      vTilde[k] = v[k] + dt * (1.0 - gamma) * a[k];
    }
  }
  // From the converged u: a = (u - u~) / (beta dt^2), v = v~ + gamma dt a on free dofs. A prescribed dof
  // moves as its condition says, not by Newmark's relations: v is the step's mean rate and a zero, as
  // Verlet keeps them (an initial velocity that disagrees with the prescribed motion would otherwise ring
  // undamped in a and v for the whole run).
  void correct(const std::vector<char>& fixed, const std::vector<double>& u, const std::vector<double>& uStart,
               const std::vector<double>& uTilde, const std::vector<double>& vTilde, std::vector<double>& v,
               std::vector<double>& a) const {
    for (std::size_t k = 0; k < u.size(); ++k) {
      if (fixed[k]) {
        v[k] = (u[k] - uStart[k]) / dt;
        a[k] = 0.0;
      } else {
        a[k] = (u[k] - uTilde[k]) / (beta * dt * dt);
        v[k] = vTilde[k] + gamma * dt * a[k];
      }
    }
  }
};


// A step that did not converge: its residual against the tolerance, or that the state left double precision.
SolverFailure stepFailure(long s, double t, const NewtonOutcome& o, double scaled, double tolerance) {
  char msg[300];
  if (!std::isfinite(o.residualDensity))
    std::snprintf(msg, sizeof msg, "Implicit: step %ld (t = %g): the residual is not finite (%g): the state left "
                  "double precision's range (check the initial conditions' magnitudes and the loads)", s, t,
                  o.residualDensity);
  else
    std::snprintf(msg, sizeof msg, "Implicit: step %ld (t = %g) did not converge in %d Newton iterations: "
                  "residual beta dt^2 |rho a - f - b| = %.3e > Absolute Tolerance %.3e", s, t, o.iterations,
                  scaled * o.residualDensity, tolerance);
  return SolverFailure(msg);
}

}  // namespace

// Newmark's scheme with beta < gamma / 2 is stable for omega dt <= 1 / sqrt(gamma / 2 - beta) (undamped; Hughes,
// The Finite Element Method, Sec. 9.1). omega is bounded by the Verlet estimate's 2 / stable step (over the
// points that move): as there, above the limit a warning, above twice it an input error, since the run would
// grow without bound and end in a non-finite residual. The inertia term rho / (beta dt^2) must be finite too.
void ImplicitSolver::check(const Model& model) const {
  if (!std::isfinite(1.0 / (opt_.beta * opt_.dt * opt_.dt)))
    throw InputError(opt_.where + ": 'Beta' dt^2 = " + num(opt_.beta * opt_.dt * opt_.dt) +
                     " is too small: the inertia term rho / (Beta dt^2) overflows double precision");
  if (!(opt_.beta < 0.5 * opt_.gamma)) return;
  const double omegaDt = 2.0 / VerletSolver::stableTimeStep(model, true) * opt_.dt;
  const double limit = 1.0 / std::sqrt(0.5 * opt_.gamma - opt_.beta);
  const std::string what = opt_.where + ": 'Beta' = " + num(opt_.beta) + " is below 'Gamma' / 2 = " +
                           num(0.5 * opt_.gamma) + ": Newmark's scheme is then stable for omega dt <= " + num(limit) +
                           ", and the highest frequency of this model gives omega dt up to " + num(omegaDt);
  if (omegaDt > 2.0 * limit)
    throw InputError(what + "; reduce 'Fixed dt' or raise 'Beta' to 'Gamma' / 2 or more");
  warn(what + (omegaDt > limit ? " (above the limit: the run may grow without bound)" : ""));
}

void ImplicitSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                         const std::vector<double>& times, StepObserver& observer) {
  using Clock = std::chrono::steady_clock;
  const SolverResume* resume = takeResume();
  const double t0 = times.front(), t1 = times.back(), dt = opt_.dt;
  const long steps = stepCount(t0, t1, dt);
  if (steps < 1)
    throw InputError(opt_.where + ": 'Fixed dt' = " + num(dt) + " exceeds Final Time - Initial Time = " + num(t1 - t0) +
                     ": no step");
  const bool root = model.layout().rank() == 0;
  if (std::fabs(t0 + steps * dt - t1) > 1e-9 * std::fabs(t1 - t0))
    warn(opt_.where + ": Final Time - Initial Time is not a multiple of 'Fixed dt': the run ends at t = " +
         num(t0 + steps * dt) + " (Peridigm's floor)");
  const int n = model.numDofs();
  const std::vector<char>& fixed = model.prescribedMask();
  const Newmark nm{dt, opt_.beta, opt_.gamma};

  Inertia inertia;  // rho / (beta dt^2) on free dofs: the mass term of the step's residual and tangent
  inertia.coefficient.assign(n, 0.0);
  inertia.predictor.assign(n, 0.0);
  for (int k = 0; k < n; ++k)
    if (!fixed[k]) inertia.coefficient[k] = model.density()[k / 3] / (opt_.beta * dt * dt);
  NewtonKrylov engine(opt_.newton);

  std::vector<double> f(n), b(n), a(n, 0.0), uStart(n), vTilde(n);
  // a is all a later step needs besides u, v and the committed state (bit for bit: not recomputed from f).
  const SolverCarry carry{{{"Acceleration", &a}}, {}};
  if (resume) {
    a = resume->vector("Acceleration");
  } else {
    model.applyPrescribed(t0, u.data(), true);
    atStep(CheckPoint{"Implicit", 0, t0}, [&] { model.internalForce(u.data(), f.data()); });
    model.commit();
    model.bodyForce(t0, b.data());
    // Newmark's consistent start is a = M^-1 (f + b); Peridigm's executeImplicit never evaluates it and starts
    // from a = 0 (Peridigm.cpp: `a` is first written by the first step's corrector), its decks' default.
    if (opt_.initialEquationOfMotion)
      for (int k = 0; k < n; ++k) a[k] = fixed[k] ? 0.0 : (f[k] + b[k]) / model.density()[k / 3];
    requireFiniteState(model, CheckPoint{"Implicit", 0, t0}, u, v, f, finiteProbe(u) + finiteProbe(v) + finiteProbe(f));
    observer.onStep(StepReport{0, t0, 0, 0.0, 0.0, 0.0, &carry}, u, v, f);
  }
  if (root)
    std::printf("Implicit: Newmark beta = %g, gamma = %g, dt = %.6g s, %ld steps\n", opt_.beta, opt_.gamma, dt, steps);

  const double scaled = opt_.beta * dt * dt;  // Peridigm's residual = scaled x force-density residual
  const long firstStep = resume ? resume->step + 1 : 1;
  const ProgressClock progress(firstStep, steps);
  for (long s = firstStep; s <= steps; ++s) {
    const auto start = Clock::now();
    const double t = t0 + s * dt;
    model.requireFiniteLoads(t);
    uStart = u;
    nm.predict(u, v, a, inertia.predictor, vTilde);
    u = inertia.predictor;
    model.applyPrescribed(t, u.data());
    const NewtonOutcome o = engine.solveWithBreaks(model, u, t, &inertia);
    if (!o.converged) {
      model.rollback();
      u = uStart;
      throw stepFailure(s, t, o, scaled, opt_.absoluteTolerance);
    }
    // the last evaluation may have been a perturbed one
    atStep(CheckPoint{"Implicit", s, t}, [&] { model.internalForce(u.data(), f.data()); });
    model.commit();
    model.endBreakRounds();
    nm.correct(fixed, u, uStart, inertia.predictor, vTilde, v, a);
    requireFiniteState(model, CheckPoint{"Implicit", s, t}, u, v, f, finiteProbe(u) + finiteProbe(v) + finiteProbe(f));
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    if (root) {
      std::printf("time step %4ld/%ld  t = %-12.6g Newton iterations %2d (linear %4d)  residual %.3e (tol %.3e)  "
                  "wall %.2f s%s\n", s, steps, t, o.iterations, o.linearIterations, scaled * o.residualDensity,
                  opt_.absoluteTolerance, wall, progress.leftAfter(s).c_str());
      std::fflush(stdout);
    }
    StepReport report{static_cast<int>(s), t, o.iterations, scaled * o.residualDensity, opt_.absoluteTolerance, wall,
                      &carry};
    report.nonlinearIterations = o.iterations;  // Peridigm's Implicit counts each Newton iteration
    observer.onStep(report, u, v, f);
  }
  printWork(model, engine.work());
}

}  // namespace pf
