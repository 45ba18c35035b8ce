#include "AdrSolver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "LoadStepping.hpp"
#include "Model.hpp"

namespace pf {

AdrSolver::StepResult AdrSolver::relax(Model& model, std::vector<double>& u, double t,
                                       const std::vector<double>& uStart) const {
  const int n = model.numDofs();
  const bool root = model.layout().rank() == 0;
  const std::vector<char>& fixed = model.prescribedMask();
  // Fictitious density lambda_ii = dt^2/4 sum_j |K_ij| with pseudo time step dt = 1 (Kilic & Madenci Eq. 17).
  std::vector<double> lambda(n);
  for (int k = 0; k < n; ++k) lambda[k] = 0.25 * opt_.safetyFactor * model.stiffnessBound()[k / 3];
  std::vector<double> f(n), b(n), r(n), rOld(n), v(n, 0.0);
  model.bodyForce(t, b.data());
  model.internalForce(u.data(), f.data());
  ResidualNorms nr = residualNorms(model, f, b);
  double tol = 0;
  int it = 0;
  for (;; ++it) {
    tol = opt_.relativeTolerance * nr.load;
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
      model.layout().comm().SumAll(loc, glob, 2);
      if (glob[0] > 0 && glob[1] > 0) c = std::min(2.0 * std::sqrt(glob[0] / glob[1]), 1.999);
      for (int k = 0; k < n; ++k) v[k] = ((2.0 - c) * v[k] + 2.0 * r[k] / lambda[k]) / (2.0 + c);
    } else {
      for (int k = 0; k < n; ++k) v[k] = 0.5 * r[k] / lambda[k];
    }
    for (int k = 0; k < n; ++k) u[k] += v[k];
    rOld = r;
    model.internalForce(u.data(), f.data());
    nr = residualNorms(model, f, b);
    if (opt_.verbose && root) std::printf("  ADR it %d  residual %.6e  damping %.4f\n", it + 1, nr.residual, c);
  }
  return {it, nr.residual, tol};
}

void AdrSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v, double t0, double t1,
                    StepObserver& observer) {
  using Clock = std::chrono::steady_clock;
  const int n = model.numDofs();
  const bool root = model.layout().rank() == 0;
  std::vector<double> f(n), uStepStart(n), duPrev(n, 0.0);
  model.applyPrescribed(t0, u.data());
  model.internalForce(u.data(), f.data());
  std::fill(v.begin(), v.end(), 0.0);
  observer.onStep(StepReport{0, t0, 0, 0.0, 0.0, 0.0}, u, v, f);

  const double dt = (t1 - t0) / opt_.loadSteps;
  for (int step = 1; step <= opt_.loadSteps; ++step) {
    auto start = Clock::now();
    const double t = t0 + (t1 - t0) * step / opt_.loadSteps;
    uStepStart = u;
    predictStep(model, t, u, duPrev);
    const StepResult res = relax(model, u, t, uStepStart);
    model.internalForce(u.data(), f.data());  // f and trial state at the converged u
    model.commit();
    // Reported velocity is the load-step rate du/dt, as Peridigm's quasi-static solvers write it.
    for (int k = 0; k < n; ++k) {
      duPrev[k] = u[k] - uStepStart[k];
      v[k] = duPrev[k] / dt;
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    if (root) {
      std::printf("load step %4d/%d  t = %-12.6g iterations %7d  residual %.3e (tol %.3e)  wall %.2f s\n", step,
                  opt_.loadSteps, t, res.iterations, res.residual, res.tolerance, wall);
      std::fflush(stdout);
    }
    observer.onStep(StepReport{step, t, res.iterations, res.residual, res.tolerance, wall}, u, v, f);
  }
}

}  // namespace pf
