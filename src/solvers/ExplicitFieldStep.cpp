#include "ExplicitFieldStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/InputError.hpp"
#include "Solver.hpp"
#include "model/Model.hpp"

namespace pf {

ExplicitFieldStep::ExplicitFieldStep(const Model& model, std::string field, const std::string& where)
    : field_(std::move(field)) {
  const int n = model.numOwned();
  if (!model.fields().has(field_))
    throw InputError(where + ": 'Solve For " + field_ + "' = true but no block has a term on it: give a block's "
                             "material 'Specific Heat Capacity' with 'Thermal Conductivity' or 'Taylor-Quinney "
                             "Coefficient'");
  capacity_.assign(n, 0.0), diag_.assign(n, 0.0), T_.assign(n, 0.0), rate_.assign(n, 0.0), source_.assign(n, 0.0);
  surface_.assign(n, 0.0);
  model.fieldCapacity(field_, capacity_.data());
  double missing = 0.0;
  for (double c : capacity_) missing = c > 0.0 ? missing : 1.0;
  if (model.max(missing) > 0.0)
    throw InputError(where + ": 'Solve For " + field_ + "' = true needs a heat capacity at every point: 'Density' and "
                             "'Specific Heat Capacity' in every block's material");
  conducts_ = model.hasOperator(field_);
  heats_ = model.hasFieldSource(field_);
  if (conducts_) model.fieldDiagonal(field_, diag_.data());
  // Broken bonds only lower D_i, so the step stays stable as a body fails.
  double rate = 0.0;  // max D_i / C_i
  for (int i = 0; i < n; ++i) rate = std::max(rate, diag_[i] / capacity_[i]);
  rate = model.max(rate);
  stable_ = rate > 0.0 ? kSafety / rate : std::numeric_limits<double>::infinity();
}

long ExplicitFieldStep::subSteps(double dt) const {
  if (std::isinf(stable_)) return 1;
  return std::max(1L, static_cast<long>(std::ceil(dt / stable_ - 1e-12)));
}

void ExplicitFieldStep::advance(Model& model, double dt, bool mechanicsEvaluated) {
  const int n = model.numOwned();
  StateStore& state = model.state();
  const std::vector<char>& mask = model.fields().prescribedMask(field_);
  // The trial holds the committed values with the step end's prescribed ones (the evaluation's, or updateFields).
  std::copy(state.trial(field_), state.trial(field_) + n, T_.begin());
  if (heats_) {
    // The blocks' sources read the step's mechanical state: only after a force evaluation.
    if (mechanicsEvaluated) model.fieldSource(field_, dt, source_.data());
    model.fieldSurfaceSource(field_, surface_.data());
    for (int i = 0; i < n; ++i) source_[i] = mechanicsEvaluated ? source_[i] + surface_[i] : surface_[i];
  }
  const long m = subSteps(dt);
  const double h = dt / static_cast<double>(m);
  for (long k = 0; k < m; ++k) {
    if (conducts_) model.fieldRate(field_, T_.data(), rate_.data());
    for (int i = 0; i < n; ++i)
      if (!mask[i]) T_[i] += h * (rate_[i] + source_[i]) / capacity_[i];
  }
  taken_ += m;
  double probe = 0.0;  // non-finite iff some value is
  for (int i = 0; i < n; ++i) probe += T_[i];
  if (!std::isfinite(model.sum(probe)))
    throw SolverFailure("the " + field_ + " field is not finite after the explicit step of length " +
                        std::to_string(dt) + " (" + std::to_string(m) + " sub-steps)");
  std::copy(T_.begin(), T_.end(), state.trial(field_));
  model.fields().updateChange(field_, state);  // the ghosts follow at the next evaluation's impose
  // Flux_Divergence: the conduction of the last sub-step's start (Peridigm's output is L(T)).
  const std::string& rateName = model.fields().rateName(field_);
  if (!rateName.empty()) std::copy(rate_.begin(), rate_.end(), state.trial(rateName));
}

}  // namespace pf
