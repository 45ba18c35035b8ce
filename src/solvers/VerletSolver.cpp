#include "VerletSolver.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <cstdio>
#include <ctime>

#include "ExplicitFieldStep.hpp"
#include "FiniteCheck.hpp"
#include "Progress.hpp"
#include "PeridigmTimeStep.hpp"
#include "VerletPeridigm.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "model/Model.hpp"

namespace pf {

SolverEntry VerletSolver::entry() {
  using S = ParameterSpec;
  SolverEntry e;
  e.name = "Verlet";
  e.doc = "explicit central-difference (velocity-Verlet) time integration with the lumped density";
  e.dynamic = true;
  e.mayAlsoSolve = {"Temperature"};
  e.mayOmitOwn = true;
  e.parameters = {S::real("Fixed dt", "time step; the run takes floor((Final Time − Initial Time) / dt) steps, as "
                                      "Peridigm; default: `Safety Factor` × the stable step estimate, shortened to end on "
                                      "Final Time; above that estimate a warning, above 2 × it an input error").positive(),
                  S::real("Safety Factor", "multiplies the stable step estimate; the step above the stiffness bound a "
                                           "warning, above 2 × it an input error (as `Fixed dt`)").byDefault("0.8").positive(),
                  S::text("Stable Step Estimate",
                          "without `Fixed dt`: `Peridigm`'s critical step, min sqrt(2ρ / Σ V_j 18K/(πδ⁴|ξ|)), with "
                          "Peridigm's floor((Final Time − Initial Time)/dt) steps; `Stiffness Bound`: 2/sqrt(max bound/ρ) "
                          "of every material's own stiffness, dt shortened to end on Final Time")
                      .byDefault("Peridigm").oneOf({"Peridigm", "Stiffness Bound"}),
                  S::flag("Allow Unstable Time Step",
                          "accept a `Fixed dt` or `Safety Factor` more than 2 × the stable step estimate (otherwise an "
                          "input error)")
                      .byDefault("false"),
                  S::text("Prescribed Velocity",
                          "the velocity a prescribed component carries (and is written with): Half Kick (Peridigm's: "
                          "the step's rate Δu/dt plus dt/2 (f + b)/ρ, its second half kick applied to every "
                          "component) or Step Rate (Δu/dt alone, the component's own motion: 0 for a held one)")
                      .oneOf({"Half Kick", "Step Rate"})
                      .byDefault("Half Kick")};
  e.create = [](const ParameterValues& p, const ParamTree&) {
    VerletOptions o;
    o.fixedDt = p.get("Fixed dt", 0.0);
    o.safetyFactor = p.get("Safety Factor");
    o.peridigmEstimate = p.text("Stable Step Estimate") == "Peridigm";
    o.allowUnstable = p.flag("Allow Unstable Time Step");
    o.prescribedHalfKick = p.text("Prescribed Velocity") == "Half Kick";
    o.where = p.where();
    return std::unique_ptr<Solver>(new VerletSolver(o));
  };
  return e;
}

namespace {

// CPU seconds of the calling thread: unlike wall time, not inflated when the core is shared.
double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// Time spent in the internal force evaluations of the stepping loop (bond kernels plus the ghost
// import/export around them), to tell the kernel's cost from the per-step overhead of the integrator.
struct ForceTimer {
  double wall = 0.0, cpu = 0.0;
  template <class F>
  void time(F&& f) {
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = threadCpuSeconds();
    f();
    cpu += threadCpuSeconds() - c0;
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  }
};

// The acceleration the next half step uses: zero on prescribed components, (f + f_terms + b) / rho elsewhere
// (f_terms: the model's force terms, contact; empty without them).
void acceleration(const Model& model, const std::vector<double>& f, const std::vector<double>& terms,
                  const std::vector<double>& b, std::vector<double>& a) {
  const std::vector<char>& fixed = model.prescribedMask();
  for (std::size_t k = 0; k < a.size(); ++k)
    a[k] = fixed[k] ? 0.0 : (f[k] + (terms.empty() ? 0.0 : terms[k]) + b[k]) / model.density()[k / 3];
}

// The model's force terms (contact) for the integrator: their sum ft at the step's positions y (the ones the
// materials see, VerletPeridigm.hpp: Peridigm's, which its contact sees too) and half-step velocities v.
class TermForces {
 public:
  TermForces(const Model& model, bool on) : ft(on ? model.numDofs() : 0) {}
  bool on() const { return !ft.empty(); }
  double operator[](std::size_t k) const { return ft.empty() ? 0.0 : ft[k]; }
  void evaluate(Model& model, long s, double t, const std::vector<double>& y, const std::vector<double>& v) {
    timer.time([&] { atStep(CheckPoint{"Verlet", s, t}, [&] { model.termForce(s, t, y.data(), v.data(), ft.data()); }); });
  }
  // f + ft (the force Peridigm's last half kick uses at prescribed components), or f itself without terms.
  const std::vector<double>& plus(const std::vector<double>& f) {
    if (ft.empty()) return f;
    sum_.resize(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) sum_[k] = f[k] + ft[k];
    return sum_;
  }
  std::vector<double> ft;  // 3 per owned node; empty without terms
  ForceTimer timer;        // the terms' evaluations (contact: search, ghost updates and the law)

 private:
  std::vector<double> sum_;
};

}  // namespace

double VerletSolver::stableTimeStep(const Model& model, bool freeOnly) {
  double w2 = 0.0;  // largest eigenvalue bound of M^-1 K (over the points that move freely)
  const std::vector<char>& fixed = model.prescribedMask();
  for (int i = 0; i < model.numOwned(); ++i)
    if (!freeOnly || !(fixed[3 * i] && fixed[3 * i + 1] && fixed[3 * i + 2]))
      w2 = std::max(w2, model.stiffnessBound()[i] / model.density()[i]);
  w2 = model.max(w2);
  if (freeOnly && w2 == 0.0) return std::numeric_limits<double>::infinity();  // no free point: nothing to go unstable
  return w2 > 0 ? 2.0 / std::sqrt(w2) : 1.0;
}

double VerletSolver::timeStep(const Model& model, const ExplicitFieldStep* heat) const {
  if (opt_.fixedDt > 0) return opt_.fixedDt;
  // A coupled run steps at the mechanics' pace and sub-cycles the field; a thermal-only one at the field's.
  if (!advances("Displacement")) return opt_.safetyFactor * heat->stableStep();
  return opt_.safetyFactor * (opt_.peridigmEstimate ? peridigmCriticalTimeStep(model) : stableTimeStep(model));
}

namespace {

// The growth per step of leapfrog's fastest mode at h = omega dt = 2 dt / stable > 2: the larger root of
// lambda^2 - (h^2 - 2) lambda + 1 = 0 (1 at or below the stability limit).
double unstableGrowth(double dtOverStable) {
  const double h2 = 4.0 * dtOverStable * dtOverStable, b = h2 - 2.0;
  return b <= 2.0 ? 1.0 : 0.5 * (b + std::sqrt(b * b - 4.0));
}

}  // namespace

void VerletSolver::check(const Model& model, const RunStart& start) const {
  if (advances("Temperature")) {
    const ExplicitFieldStep heat(model, "Temperature", opt_.where);  // throws InputError for a field it cannot step
    if (!advances("Displacement") && opt_.fixedDt <= 0 && std::isinf(heat.stableStep()))
      throw InputError(opt_.where + ": a thermal-only run without conduction has no stable step: give 'Fixed dt'");
  }
  if (!advances("Displacement")) return;  // no mechanics: only the thermal step bounds dt
  if (opt_.fixedDt <= 0 && !opt_.peridigmEstimate) {
    // The default step is Safety Factor x the estimate: bounded as a Fixed dt is (a factor of 1e300 would step
    // over the whole interval at once and end "done" with a blown-up state).
    char msg[160];
    std::snprintf(msg, sizeof msg, "'Safety Factor' = %g makes the time step %g times the stable step estimate",
                  opt_.safetyFactor, opt_.safetyFactor);
    if (opt_.safetyFactor > kRefuseFactor && !opt_.allowUnstable)
      throw InputError(opt_.where + ": " + msg + "; above " + std::to_string(static_cast<int>(kRefuseFactor)) +
                       " it is refused unless 'Allow Unstable Time Step' is true");
    if (opt_.safetyFactor > 1.0) warn(opt_.where + ": " + msg + "; the run may go unstable");
    return;
  }
  // Only points with a free component can go unstable: a point whose motion is prescribed in all three
  // directions is moved by its condition, not by the integrator (Peridigm's fully prescribed decks, the affine
  // material point). The default step (timeStep) still bounds every point, as Peridigm's does.
  // Peridigm's estimate is checked as a Fixed dt is: it is no bound on every model's stiffness.
  const double stable = stableTimeStep(model, true);
  if (std::isinf(stable)) return;
  const double critical = opt_.fixedDt > 0 ? 0.0 : peridigmCriticalTimeStep(model);
  const double dt = opt_.fixedDt > 0 ? opt_.fixedDt : opt_.safetyFactor * critical;
  char what[120], msg[320];
  if (opt_.fixedDt > 0)
    std::snprintf(what, sizeof what, "Fixed dt = %g", dt);
  else
    std::snprintf(what, sizeof what, "'Safety Factor' = %g x Peridigm's critical step %g = %g", opt_.safetyFactor,
                  critical, dt);
  std::snprintf(msg, sizeof msg, "%s exceeds the stable time step estimate %g (%.3g times)", what, stable, dt / stable);
  // A body at rest that nothing moves has only the round-off of its forces at rest to amplify (Peridigm's parsing
  // decks, e.g. VariableHorizonParsing: no condition, 2 steps at 4.3 times the estimate): over few enough steps
  // that this grows at most 1e6-fold (1e-16 of the coordinates stays below 1e-10) the step only warns.
  if (dt > kRefuseFactor * stable && !opt_.allowUnstable && start.atRest) {
    const double steps = std::floor((start.endTime - start.startTime) / dt);
    const double growth = std::pow(unstableGrowth(dt / stable), steps);
    if (growth <= 1e6) {
      char rest[200];
      std::snprintf(rest, sizeof rest, "; nothing moves the body and its %.0f step(s) amplify round-off at most %.3g-fold",
                    steps, growth);
      warn(opt_.where + ": " + msg + rest);
      return;
    }
  }
  if (dt > kRefuseFactor * stable && !opt_.allowUnstable)
    throw InputError(opt_.where + ": " + msg + "; above " + std::to_string(static_cast<int>(kRefuseFactor)) +
                     " times it is refused unless 'Allow Unstable Time Step' is true (or 'Stable Step Estimate' = "
                     "'Stiffness Bound')");
  if (dt > stable) warn(opt_.where + ": " + msg + "; the run may go unstable");
}

// The step's end state at t: the force at positions y and velocities v (mechanics; v is Peridigm's velocity at the
// evaluation, the half-step one with the conditions' rate at prescribed components, which its correspondence rate
// reads: Model::setVelocity, for this evaluation only) or only the conditions of t, then the field advanced over
// dt (0: the start, nothing to advance), then the commit.
void VerletSolver::evaluate(Model& model, ExplicitFieldStep* heat, long step, double t, double dt,
                            const std::vector<double>& y, const std::vector<double>& v, std::vector<double>& f) const {
  const CheckPoint at{"Verlet", step, t};
  if (advances("Displacement")) {
    model.setVelocity(v.data());
    atStep(at, [&] { model.internalForceAt(y.data(), f.data()); });
    model.setVelocity(nullptr);  // other evaluations (another solver's, an output's) have no velocities
  } else {
    model.updateFields();
  }
  if (heat && dt > 0.0) atStep(at, [&] { heat->advance(model, dt, advances("Displacement")); });
  model.commit();  // an explicit step is complete once its force (and field) is evaluated
}

// The run's last lines: where the stepping time went, and the deterministic work counts. Collective (the force
// terms sum their counts over the ranks).
static void printRunSummary(const Model& model, bool root, const ForceTimer& forceTime, double wall, double cpu,
                            const ExplicitFieldStep* heat, const TermForces& terms) {
  if (root)
    std::printf("Verlet: force evaluations %.3f s wall, %.3f s CPU (rank 0) of %.3f s wall, %.3f s CPU stepping\n",
                forceTime.wall, forceTime.cpu, wall, cpu);
  if (root && heat) std::printf("Verlet: Temperature sub-steps %ld\n", heat->subStepsTaken());
  if (terms.on()) {
    const std::string work = model.termWorkSummary();
    if (root) std::printf("Verlet: force terms %.3f s wall (rank 0): %s\n", terms.timer.wall, work.c_str());
  }
}

std::unique_ptr<ExplicitFieldStep> VerletSolver::heatStep(Model& model) const {
  if (!advances("Temperature")) return nullptr;
  model.fields().setSolved("Temperature");
  return std::make_unique<ExplicitFieldStep>(model, "Temperature", opt_.where);
}

long VerletSolver::stepCount(double duration, double& dt, const SolverResume* resume) const {
  if (resume) {  // the interrupted run's step (its stable-step estimate may differ in the last bit at another np)
    dt = resume->scalar("dt");
    return static_cast<long>(resume->scalar("steps"));
  }
  // A Fixed dt takes floor(duration / dt) steps, as Peridigm (Peridigm.cpp, executeExplicit): a quotient that rounds
  // below an integer (0.01 / 2e-5 = 499.99999999999994) takes one step less, ending before the end time. The default
  // step is shortened to land on it (ceil, a quotient within 1e-9 above an integer taken as it).
  if (!landsOnEnd()) return std::max(1L, static_cast<long>(std::floor(duration / dt)));
  const long steps = std::max(1L, static_cast<long>(std::ceil(duration / dt - 1e-9)));
  dt = duration / steps;
  return steps;
}

void VerletSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                       const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  const double t0 = times.front(), t1 = times.back();
  using Clock = std::chrono::steady_clock;
  const int n = model.numDofs();
  const bool mechanics = advances("Displacement");
  std::unique_ptr<ExplicitFieldStep> heat = heatStep(model);
  double dt = timeStep(model, heat.get());
  long steps = stepCount(t1 - t0, dt, resume);
  const bool root = model.layout().rank() == 0;
  if (root) std::printf("Verlet: dt = %.6g s, %ld steps\n", dt, steps);
  if (root && heat)
    std::printf("Verlet: Temperature by %ld explicit sub-step(s) per step (stable step %.6g s)\n", heat->subSteps(dt),
                heat->stableStep());
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double>& rho = model.density();
  std::vector<double> f(n), b(n), a(n), uPrev(n), y(n);
  TermForces terms(model, mechanics && model.hasForceTerms());
  // f and the terms' ft are all a later step needs of this one besides u, v and the committed state.
  SolverCarry carry{{{"Force_Density", &f}}, {{"dt", dt}, {"steps", static_cast<double>(steps)}}};
  if (terms.on()) carry.vectors.push_back({"Force_Terms", &terms.ft});
  if (resume) {
    f = resume->vector("Force_Density");
    if (terms.on()) terms.ft = resume->vector("Force_Terms");
    model.bodyForce(resume->time, b.data());
  } else {
    model.applyPrescribed(t0, u.data(), true);
    verletPositions(model, u, u, v, 0.0, y);
    evaluate(model, heat.get(), 0, t0, 0.0, y, v, f);
    if (terms.on()) terms.evaluate(model, 0, t0, y, v);
    model.bodyForce(t0, b.data());
  }
  if (mechanics) acceleration(model, f, terms.ft, b, a);  // a thermal-only run leaves u and v alone
  if (!resume) {
    requireFiniteState(model, CheckPoint{"Verlet", 0, t0}, u, v, f,
                       finiteProbe(u) + finiteProbe(v) + finiteProbe(f));
    observer.onStep(StepReport{0, t0, 0, 0.0, 0.0, 0.0, &carry}, u, v, f);
  }

  const long every = std::max(1L, steps / 20);
  ForceTimer forceTime;
  const double runCpu0 = threadCpuSeconds();
  const ProgressClock progress(resume ? resume->step + 1 : 1, steps);  // its clock: the stepping's wall time
  for (long s = resume ? resume->step + 1 : 1; s <= steps; ++s) {
    auto start = Clock::now();
    const double t = (s == steps && landsOnEnd()) ? t1 : t0 + s * dt;
    uPrev = u;
    const double rate = 1.0 / (t - (t0 + (s - 1) * dt));  // Peridigm's DirichletIncrementBC: change / (t - t_prev)
    for (int k = 0; k < n; ++k) {
      v[k] += 0.5 * dt * a[k];
      u[k] += dt * v[k];
    }
    if (!model.rigidWalls().empty()) model.enforceRigidWalls(dt, u.data(), v.data(), a.data());
    model.applyPrescribed(t, u.data());
    for (int k = 0; k < n; ++k)
      if (fixed[k]) v[k] = (u[k] - uPrev[k]) * rate;
    verletPositions(model, uPrev, u, v, dt, y);
    forceTime.time([&] { evaluate(model, heat.get(), s, t, dt, y, v, f); });
    if (terms.on()) terms.evaluate(model, s, t, y, v);
    if (model.hasBodyForce() && mechanics) model.bodyForce(t, b.data());
    double probe = 0.0;  // non-finite iff some u, v or f is (the check reads the state, never alters it)
    for (int k = 0; k < n; ++k) {
      a[k] = fixed[k] || !mechanics ? 0.0 : (f[k] + terms[k] + b[k]) / rho[k / 3];
      if (!fixed[k]) v[k] += 0.5 * dt * a[k];
      probe += u[k] + v[k] + f[k] + terms[k];
    }
    if (opt_.prescribedHalfKick && mechanics) halfKickPrescribed(fixed, rho, terms.plus(f), b, dt, v);
    requireFiniteState(model, CheckPoint{"Verlet", s, t}, u, v, f, probe);
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    observer.onStep(StepReport{static_cast<int>(s), t, 0, 0.0, 0.0, wall, &carry}, u, v, f);
    if (root && (s % every == 0 || s == steps))
      std::printf("step %ld/%ld  t = %.6g  wall %.2f s%s\n", s, steps, t, progress.elapsed(),
                  progress.leftAfter(s).c_str()), std::fflush(stdout);
  }
  printRunSummary(model, root, forceTime, progress.elapsed(), threadCpuSeconds() - runCpu0, heat.get(), terms);
}

}  // namespace pf
