#include "StepEquations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "NewtonKrylov.hpp"
#include "core/Material.hpp"
#include "model/Model.hpp"

namespace pf {

StepResidual::StepResidual(Model& model, double t, std::vector<double> xbar, double scale, const Inertia* inertia,
                           NewtonWork* work)
    : model_(model), xbar_(std::move(xbar)), scale_(scale), inertia_(inertia), work_(work), u_(model.numDofs()),
      f_(model.numDofs()), fAccepted_(model.numDofs()), b_(model.numDofs()), load_(model.numDofs()),
      loadAccepted_(model.numDofs()) {
  model.bodyForce(t, b_.data());
  load_ = b_;
}

bool StepResidual::evaluate(const double* x, double* F, bool accepted) {
  const WorkTimer timer(work_ ? &work_->residualSeconds : nullptr);
  if (work_) ++work_->residuals;
  const std::vector<char>& fixed = model_.prescribedMask();
  const int n = model_.numDofs();
  std::copy(x, x + n, u_.begin());
  lastCall_ = -1;
  try {
    model_.internalForce(u_.data(), f_.data());
  } catch (const ConstitutiveFailure&) {
    return false;
  }
  if (work_) lastCall_ = work_->modelCalls();
  if (inertia_)
    for (int k = 0; k < n; ++k)
      if (!fixed[k]) load_[k] = b_[k] - inertia_->coefficient[k] * (x[k] - inertia_->predictor[k]);
  for (int k = 0; k < n; ++k) F[k] = fixed[k] ? scale_ * (x[k] - xbar_[k]) : -(f_[k] + load_[k]);
  if (accepted) {
    fAccepted_ = f_;
    loadAccepted_ = load_;
    if (onResidual_) onResidual_(norms());
  }
  return true;
}

const std::vector<double>* StepResidual::lastForceAt(const std::vector<double>& x) const {
  if (!work_ || lastCall_ != work_->modelCalls() || x.size() != u_.size()) return nullptr;
  return std::equal(x.begin(), x.end(), u_.begin()) ? &f_ : nullptr;
}

ResidualNorms StepResidual::norms() const { return residualNorms(model_, fAccepted_, loadAccepted_); }

StepTangent::StepTangent(Model& model, double scale, const Inertia* inertia, bool exact, NewtonWork* work)
    : model_(model), scale_(scale), inertia_(inertia), exact_(exact && model.hasExactTangent()), work_(work),
      u_(model.numDofs()), df_(model.numDofs()), f0_(model.numDofs()), up_(model.numDofs()) {
  double shortest = std::numeric_limits<double>::max();
  for (double r : model.layout().family().refLength) shortest = std::min(shortest, r);
  double g = 0, neg = -shortest;
  model.layout().comm().max(&neg, &g, 1);
  step_ = 1e-7 * (-g);
}

bool StepTangent::lineariseAt(const double* x) {
  std::copy(x, x + model_.numDofs(), u_.begin());
  const WorkTimer timer(work_ ? &work_->linearisationSeconds : nullptr);
  if (work_) ++work_->linearisations;
  if (exact_) {
    const bool ok = model_.lineariseAt(u_.data());
    if (work_) work_->tangentBytes = std::max(work_->tangentBytes, static_cast<double>(model_.linearisationBytes()));
    return ok;
  }
  // the difference's base force
  try {
    model_.internalForce(u_.data(), f0_.data());
  } catch (const ConstitutiveFailure&) {
    return false;
  }
  return true;
}

bool StepTangent::apply(const double* dx, double* y) {
  const WorkTimer timer(work_ ? &work_->tangentSeconds : nullptr);
  if (work_) ++work_->tangentProducts;
  const std::vector<char>& fixed = model_.prescribedMask();
  const int n = model_.numDofs();
  if (exact_) {
    if (!model_.forceDerivative(dx, df_.data())) return false;
  } else {
    double local = 0, vmax = 0;
    for (int k = 0; k < n; ++k) local = std::max(local, std::fabs(dx[k]));
    model_.layout().comm().max(&local, &vmax, 1);
    if (vmax == 0) {
      std::fill(df_.begin(), df_.end(), 0.0);
    } else {
      const double h = step_ / vmax;
      for (int k = 0; k < n; ++k) up_[k] = u_[k] + h * dx[k];
      try {
        model_.internalForce(up_.data(), df_.data());
      } catch (const ConstitutiveFailure&) {
        return false;
      }
      for (int k = 0; k < n; ++k) df_[k] = (df_[k] - f0_[k]) / h;
    }
  }
  for (int k = 0; k < n; ++k)
    y[k] = fixed[k] ? scale_ * dx[k] : -df_[k] + (inertia_ ? inertia_->coefficient[k] * dx[k] : 0.0);
  return true;
}

}  // namespace pf
