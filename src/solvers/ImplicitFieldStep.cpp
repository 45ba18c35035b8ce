#include "ImplicitFieldStep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ScalarKrylov.hpp"
#include "Solver.hpp"
#include "core/InputError.hpp"
#include "model/Model.hpp"

namespace pf {

namespace {
// Of the Krylov solve of one Newton iteration, relative to its right-hand side: tight, so that one iteration
// meets any Relative Tolerance a deck asks (the operator is linear).
constexpr double kKrylovTolerance = 1e-12;
}  // namespace

ImplicitFieldStep::ImplicitFieldStep(const Model& model, std::string field, ImplicitFieldOptions o)
    : field_(std::move(field)), opt_(std::move(o)) {
  // A transient step also runs without conduction (adiabatic plastic heating: T = T_n + s dt / C); a steady one
  // has nothing to solve without it.
  if (opt_.transient && !model.fields().has(field_))
    throw InputError(opt_.where + ": " + opt_.transientBy + " but no block has a term on the " + field_ + ": give a "
                                  "block's material 'Specific Heat Capacity' with 'Thermal Conductivity' or "
                                  "'Taylor-Quinney Coefficient'");
  if (!opt_.transient && !model.hasOperator(field_))
    throw InputError(opt_.where + ": no block conducts heat: give a block a material with conduction (Material Model "
                                  "'Diffusion', or a solid with 'Thermal Conductivity')");
  heats_ = model.hasFieldSource(field_);
  if (opt_.transient && !model.capacityEverywhere(field_))
    throw InputError(opt_.where + ": " + opt_.transientBy + " needs 'Density' and 'Specific Heat Capacity' in every "
                                  "block's material (a point without heat capacity)");
}

ImplicitFieldStep::Outcome ImplicitFieldStep::advance(Model& model, double tPrev, double t, bool mechanicsEvaluated) {
  const int n = model.numOwned();
  StateStore& state = model.state();
  const std::vector<char>& mask = model.fields().prescribedMask(field_);
  const std::vector<double>& V = model.volume();
  auto sum = [&](double x) { return model.sum(x); };
  T_.resize(n), rate_.assign(n, 0.0);
  std::vector<double>& T = T_;
  std::vector<double>& rate = rate_;
  // Backward Euler: C (T - T_n) / dt = L(T) + s; steady: L(T) + s = 0 (s: the surface conditions at t and the
  // blocks' sources over the step). R = L(T) + s - C (T - T_n) / dt at the free points.
  const double dt = t - tPrev;
  const double inertia = opt_.transient ? 1.0 / dt : 0.0;
  std::vector<double> Tn(state.committed(field_), state.committed(field_) + n), C(n), diag(n), inv(n), r(n), b(n),
      d(n), source(n);
  model.fieldCapacity(field_, C.data());
  model.fieldSurfaceSource(field_, source.data());  // Heat Flux, Convection's ambient part, at t (applyPrescribed)
  if (heats_ && mechanicsEvaluated) {
    // The blocks' sources (plastic heating) read the step's trial mechanical state, before the field's own update.
    std::vector<double> blocks(n);
    model.fieldSource(field_, dt, blocks.data());
    for (int i = 0; i < n; ++i) source[i] += blocks[i];
  }
  auto residualOf = [&] {
    model.fieldRate(field_, T.data(), rate.data());
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
      r[i] = mask[i] ? 0.0 : rate[i] + source[i] - inertia * C[i] * (T[i] - Tn[i]);
      s += r[i] * r[i];
    }
    return std::sqrt(sum(s));
  };
  std::copy(Tn.begin(), Tn.end(), state.trial(field_));
  model.updateFields();  // prescribed values of t on the committed field
  std::copy(state.trial(field_), state.trial(field_) + n, T.begin());
  Outcome o;
  o.residual = residualOf();
  double reaction = 0.0;  // Peridigm's steady rule: |L(T) V| over the held points at the step's start
  for (int i = 0; i < n; ++i) reaction += mask[i] ? rate[i] * V[i] * rate[i] * V[i] : 0.0;
  const double scale = opt_.transient ? o.residual : std::sqrt(sum(reaction));
  o.tolerance = opt_.absoluteTolerance > 0.0 ? opt_.absoluteTolerance : opt_.relativeTolerance * scale;
  model.fieldDiagonal(field_, diag.data());
  for (int i = 0; i < n; ++i) {
    const double jii = diag[i] + inertia * C[i];  // |dR_i / dT_i|
    inv[i] = mask[i] || !(jii > 0.0) ? 1.0 : -1.0 / jii;
  }
  // dR/dT on a correction that is 0 at the held points: L(x) - C x / dt at the free ones, x itself at those.
  auto apply = [&](const double* x, double* y) {
    model.fieldRate(field_, x, y);
    for (int i = 0; i < n; ++i) y[i] = mask[i] ? x[i] : y[i] - inertia * C[i] * x[i];
  };
  while (o.residual > o.tolerance && o.iterations < opt_.maxIterations) {
    for (int i = 0; i < n; ++i) b[i] = -r[i];
    // An unconverged Krylov solve still improves T; the Newton loop's residual test decides.
    bicgstab(apply, inv, b, d, kKrylovTolerance, 10 * model.layout().numGlobal() + 100, sum);
    for (int i = 0; i < n; ++i) T[i] += mask[i] ? 0.0 : d[i];
    o.residual = residualOf();
    ++o.iterations;
    if (model.layout().rank() == 0 && opt_.verbose)
      std::printf("  %s iteration %d: residual %.6e (tolerance %.3e)\n", field_.c_str(), o.iterations, o.residual,
                  o.tolerance);
  }
  taken_ += o.iterations;
  if (!std::isfinite(o.residual) || o.residual > o.tolerance) {
    char msg[240];
    std::snprintf(msg, sizeof msg, ": %s step to t = %g: residual %.6e above the tolerance %.6e after %d iterations",
                  field_.c_str(), t, o.residual, o.tolerance, o.iterations);
    throw SolverFailure(opt_.where + msg);
  }
  std::copy(T.begin(), T.end(), state.trial(field_));
  model.updateFields();  // the change and the ghosts of the solved field
  const std::string& rateName = model.fields().rateName(field_);
  if (!rateName.empty()) std::copy(rate.begin(), rate.end(), state.trial(rateName));
  return o;
}

}  // namespace pf
