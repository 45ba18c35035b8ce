#include "AdrSolver.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "Material.hpp"
#include "Model.hpp"

namespace pf {
namespace {

struct Norms {
  double residual;  // || r_i V_i || over free dofs (force)
  double load;      // || f_i V_i || over prescribed dofs (reaction) + || b_i V_i ||
  double residualDensity;  // || r || over free dofs (force density, Peridigm's tolerance unit)
};

Norms norms(const Model& model, const std::vector<double>& f, const std::vector<double>& b) {
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double>& V = model.volume();
  double r2 = 0, rd2 = 0, l2 = 0, b2 = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double vol = V[k / 3];
    if (fixed[k]) {
      l2 += f[k] * f[k] * vol * vol;
    } else {
      const double r = f[k] + b[k];
      r2 += r * r * vol * vol;
      rd2 += r * r;
    }
    b2 += b[k] * b[k] * vol * vol;
  }
  double in[4] = {r2, l2, b2, rd2}, out[4];
  model.layout().comm().SumAll(in, out, 4);
  return {std::sqrt(out[0]), std::sqrt(out[1]) + std::sqrt(out[2]), std::sqrt(out[3])};
}

}  // namespace

void AdrSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v, double t0, double t1,
                    StepObserver& observer) {
  using Clock = std::chrono::steady_clock;
  const int n = model.numDofs();
  const bool root = model.layout().rank() == 0;
  const std::vector<char>& fixed = model.prescribedMask();
  // Fictitious density lambda_ii = dt^2/4 sum_j |K_ij| with pseudo time step dt = 1 (Kilic & Madenci Eq. 17).
  std::vector<double> lambda(n);
  for (int k = 0; k < n; ++k) lambda[k] = 0.25 * opt_.safetyFactor * model.stiffnessBound()[k / 3];

  std::vector<double> f(n), b(n), r(n), rOld(n), uStepStart(n), duPrev(n, 0.0);
  model.applyPrescribed(t0, u.data());
  model.internalForce(u.data(), f.data());
  model.bodyForce(t0, b.data());
  std::fill(v.begin(), v.end(), 0.0);
  observer.onStep(StepReport{0, t0, 0, 0.0, 0.0, 0.0}, u, v, f);

  for (int step = 1; step <= opt_.loadSteps; ++step) {
    auto start = Clock::now();
    const double t = t0 + (t1 - t0) * step / opt_.loadSteps;
    uStepStart = u;
    // Predictor: scale the previous step's free increment by how the prescribed increment continues
    // (exact for a linear problem under proportional loading, harmless after a reversal).
    model.applyPrescribed(t, u.data());
    double dot = 0, nn = 0;
    for (int k = 0; k < n; ++k)
      if (fixed[k]) {
        dot += (u[k] - uStepStart[k]) * duPrev[k];
        nn += duPrev[k] * duPrev[k];
      }
    double in[2] = {dot, nn}, out[2];
    model.layout().comm().SumAll(in, out, 2);
    const double alpha = out[1] > 0 ? out[0] / out[1] : 0.0;
    for (int k = 0; k < n; ++k)
      if (!fixed[k]) u[k] += alpha * duPrev[k];

    model.bodyForce(t, b.data());
    std::fill(v.begin(), v.end(), 0.0);  // pseudo-velocity of the relaxation
    model.internalForce(u.data(), f.data());
    Norms nr = norms(model, f, b);
    double tol = 0;
    int it = 0;
    for (;; ++it) {
      tol = std::max(opt_.relativeTolerance * nr.load, 0.0);
      const bool absOk = opt_.absoluteTolerance > 0 && nr.residualDensity <= opt_.absoluteTolerance;
      if (nr.residual <= tol || absOk || nr.residual == 0.0) break;
      if (it >= opt_.maxIterations) {
        model.rollback();
        char msg[256];
        std::snprintf(msg, sizeof msg,
                      "adaptive dynamic relaxation: load step %d (t = %g) did not converge in %d iterations "
                      "(residual %.3e N, tolerance %.3e N)", step, t, it, nr.residual, tol);
        throw SolverFailure(msg);
      }
      for (int k = 0; k < n; ++k) r[k] = fixed[k] ? 0.0 : f[k] + b[k];
      // Damping from the local Rayleigh quotient u^T K u / u^T u with the diagonal K_ii estimated from
      // the change of residual over the last pseudo step (Kilic & Madenci Eqs. 19-20).
      double c = 0.0;
      if (it > 0) {
        double num = 0, den = 0;
        for (int k = 0; k < n; ++k) {
          if (fixed[k] || v[k] == 0.0) continue;
          const double kii = -(r[k] - rOld[k]) / (lambda[k] * v[k]);
          const double du = u[k] - uStepStart[k];
          num += du * kii * du;
          den += du * du;
        }
        double loc[2] = {num, den}, glob[2];
        model.layout().comm().SumAll(loc, glob, 2);
        if (glob[0] > 0 && glob[1] > 0) c = std::min(2.0 * std::sqrt(glob[0] / glob[1]), 1.999);
        for (int k = 0; k < n; ++k) v[k] = ((2.0 - c) * v[k] + 2.0 * r[k] / lambda[k]) / (2.0 + c);
      } else {
        for (int k = 0; k < n; ++k) v[k] = 0.5 * r[k] / lambda[k];
      }
      for (int k = 0; k < n; ++k) u[k] += v[k];
      rOld = r;
      model.internalForce(u.data(), f.data());
      nr = norms(model, f, b);
      if (opt_.verbose && root) std::printf("  ADR it %d  residual %.6e  damping %.4f\n", it + 1, nr.residual, c);
    }
    model.commit();
    // Reported velocity is the load-step rate du/dt, as Peridigm's quasi-static solvers write it.
    const double dt = (t1 - t0) / opt_.loadSteps;
    for (int k = 0; k < n; ++k) {
      duPrev[k] = u[k] - uStepStart[k];
      v[k] = duPrev[k] / dt;
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    if (root) {
      std::printf("load step %4d/%d  t = %-12.6g iterations %7d  residual %.3e (tol %.3e)  wall %.2f s\n", step,
                  opt_.loadSteps, t, it, nr.residual, tol, wall);
      std::fflush(stdout);
    }
    observer.onStep(StepReport{step, t, it, nr.residual, tol, wall}, u, v, f);
  }
}

}  // namespace pf
