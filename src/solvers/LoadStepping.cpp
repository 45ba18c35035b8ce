#include "LoadStepping.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "FiniteCheck.hpp"
#include "Progress.hpp"
#include "SolvedStates.hpp"
#include "model/Model.hpp"
#include "Solver.hpp"

namespace pf {

ResidualNorms residualNorms(const Model& model, const std::vector<double>& f, const std::vector<double>& b) {
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double>& V = model.volume();
  double r2 = 0, rd2 = 0, l2 = 0, b2 = 0, rInf = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double vol = V[k / 3];
    if (fixed[k]) {
      l2 += f[k] * f[k] * vol * vol;
    } else {
      const double r = f[k] + b[k];
      r2 += r * r * vol * vol;
      rd2 += r * r;
      rInf = std::max(rInf, std::fabs(r * vol));
    }
    b2 += b[k] * b[k] * vol * vol;
  }
  double in[4] = {r2, l2, b2, rd2}, out[4], inf = 0;
  model.layout().comm().sum(in, out, 4);
  model.layout().comm().max(&rInf, &inf, 1);
  // model.fieldLoad(): a heated body's thermal load (0 for mechanics-only models, whose scale stays as it was).
  return {std::sqrt(out[0]), std::sqrt(out[1]) + std::sqrt(out[2]) + model.fieldLoad(), std::sqrt(out[3]),
          std::sqrt(out[0]) + 20.0 * inf};
}

void predictStep(const Model& model, double t, std::vector<double>& u, const std::vector<double>& duPrev,
                 const SolvedStates* states) {
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double> before(u);
  model.applyPrescribed(t, u.data());
  if (states && predictQuadratic(model, *states, u)) return;
  double in[2] = {0, 0}, out[2];
  for (std::size_t k = 0; k < u.size(); ++k)
    if (fixed[k]) {
      in[0] += (u[k] - before[k]) * duPrev[k];
      in[1] += duPrev[k] * duPrev[k];
    }
  model.layout().comm().sum(in, out, 2);
  const double alpha = out[1] > 0 ? out[0] / out[1] : 0.0;
  for (std::size_t k = 0; k < u.size(); ++k)
    if (!fixed[k]) u[k] += alpha * duPrev[k];
}

namespace {

// Adds a solver's own state to the loop's carry (after the loop's "Increment" and "Peak Load") and restores it from a
// resume that has it.
void carryOwn(const CarriedState& own, int n, const SolverResume* resume, SolverCarry& carry) {
  for (const auto& [name, values] : own.vectors) {
    if (resume && resume->vectors.count(name))
      *values = resume->vector(name);
    else if (values->size() != static_cast<std::size_t>(n))
      values->assign(n, 0.0);
    carry.vectors.push_back({name, values});
  }
  for (const auto& [name, value] : own.scalars) {
    if (resume && resume->scalars.count(name)) *value = resume->scalar(name);
    carry.scalars.push_back({name, *value});
  }
}

}  // namespace

void runLoadSteps(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
                  StepObserver& observer,
                  const std::function<StepStats(std::vector<double>&, std::vector<double>&, double, double, double)>& solveStep,
                  const SolverResume* resume, const CarriedState* own) {
  using Clock = std::chrono::steady_clock;
  model.requestFieldLoad();  // the load scale's thermal term (residualNorms)
  const int n = model.numDofs();
  const bool root = model.layout().rank() == 0;
  std::vector<double> f(n), duPrev(n, 0.0);
  double peakLoad = 0.0;
  SolverCarry carry{{{"Increment", &duPrev}}, {{"Peak Load", 0.0}}};  // the next step's predictor and tolerance
  if (own) carryOwn(*own, n, resume, carry);
  const double t0 = times.front();
  int steps = static_cast<int>(times.size()) - 1;
  if (resume) {
    duPrev = resume->vector("Increment");
    // A checkpoint written before the peak load was carried resumes with its own step's scale.
    if (resume->scalars.count("Peak Load")) peakLoad = resume->scalar("Peak Load");
  } else {
    model.applyPrescribed(t0, u.data(), true);
    atStep(CheckPoint{"quasi-static", 0, t0}, [&] { model.internalForce(u.data(), f.data()); });
    std::fill(v.begin(), v.end(), 0.0);
    requireFiniteState(model, CheckPoint{"quasi-static", 0, t0}, u, v, f, finiteProbe(u) + finiteProbe(f));
    observer.onStep(StepReport{0, t0, 0, 0.0, 0.0, 0.0, &carry}, u, v, f);
  }
  const int firstStep = resume ? static_cast<int>(resume->step) + 1 : 1;
  const ProgressClock progress(firstStep, steps);
  for (int step = firstStep; step <= steps; ++step) {
    const auto start = Clock::now();
    const double tA = times[step - 1], tB = times[step], dt = tB - tA;
    // A condition that is not finite at the step's end fails now, naming its expression, rather than
    // after the solver has spent its iterations (or NOX its step cuts) on a NaN load.
    model.requireFiniteLoads(tB);
    const StepStats s = solveStep(u, duPrev, tA, tB, peakLoad);
    if (s.outcome == StepStats::Outcome::Stop) return;
    if (s.outcome == StepStats::Outcome::Retry) {  // the same step again, on the changed times
      steps = static_cast<int>(times.size()) - 1;
      --step;
      continue;
    }
    peakLoad = std::max(peakLoad, s.load);
    carry.scalars[0].second = peakLoad;
    if (own)
      for (std::size_t k = 0; k < own->scalars.size(); ++k) carry.scalars[1 + k].second = *own->scalars[k].second;
    // f for output; the state is committed already
    if (s.force)
      f = *s.force;
    else
      atStep(CheckPoint{"quasi-static", step, tB}, [&] { model.internalForce(u.data(), f.data()); });
    double probe = 0.0;  // non-finite iff some u, v or f is: nothing non-finite is reported
    for (int k = 0; k < n; ++k) {
      v[k] = duPrev[k] / dt;
      probe += u[k] + v[k] + f[k];
    }
    requireFiniteState(model, CheckPoint{"quasi-static", step, tB}, u, v, f, probe);
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    if (root) {
      const std::string left = progress.leftAfter(step);
      if (s.linearIterations >= 0)
        std::printf("load step %4d/%d  t = %-12.6g Newton iterations %3d (linear %5d)  residual %.3e (tol %.3e)  wall %.2f s%s\n",
                    step, steps, tB, s.iterations, s.linearIterations, s.residual, s.tolerance, wall, left.c_str());
      else if (s.rounds >= 0)  // iterations: the total over the step's loading-balance rounds
        std::printf("load step %4d/%d  t = %-12.6g iterations %7d  LBC rounds %2d  residual %.3e (tol %.3e)  wall %.2f s%s\n",
                    step, steps, tB, s.iterations, s.rounds, s.residual, s.tolerance, wall, left.c_str());
      else
        std::printf("load step %4d/%d  t = %-12.6g iterations %7d  residual %.3e (tol %.3e)  wall %.2f s%s\n", step,
                    steps, tB, s.iterations, s.residual, s.tolerance, wall, left.c_str());
      std::fflush(stdout);
    }
    StepReport report{step, tB, s.iterations, s.residual, s.tolerance, wall, &carry};
    report.nonlinearIterations = s.nonlinearIterations;
    report.outputEveryFactor = s.outputEveryFactor;
    observer.onStep(report, u, v, f);
  }
}

}  // namespace pf
