// Model's exact tangent: each block's material linearised at one point (Material::makeLinearisation) and its
// products, for the implicit solvers' Krylov operator (solvers/StepEquations.hpp StepTangent).
#include <algorithm>

#include "Model.hpp"

namespace pf {

bool Model::hasExactTangent() const {
  for (const BlockModel& b : blocks_)
    if (!b.material->hasForceDerivative()) return false;
  return true;
}

bool Model::lineariseAt(const double* u) {
  layout_->importToOverlap(u, uOverlap_.data(), 3);
  yLinearised_.resize(yOverlap_.size());
  for (std::size_t k = 0; k < yLinearised_.size(); ++k) yLinearised_[k] = x_[k] + uOverlap_[k];
  if (linearisations_.empty())
    for (const BlockModel& b : blocks_) linearisations_.push_back(b.material->makeLinearisation());
  double failed = 0.0;
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    if (linearisations_[k] && !linearisations_[k]->update(view(blocks_[k]), yLinearised_.data(), state_)) failed = 1.0;
  return layout_->max(failed) == 0.0;
}

bool Model::forceDerivative(const double* du, double* df) {
  duOverlap_.resize(yLinearised_.size());
  layout_->importToOverlap(du, duOverlap_.data(), 3);
  std::fill(fOverlap_.begin(), fOverlap_.end(), 0.0);
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    const BlockModel& b = blocks_[k];
    if (linearisations_[k])
      linearisations_[k]->apply(view(b), duOverlap_.data(), fOverlap_.data());
    else if (!b.material->forceDerivative(view(b), yLinearised_.data(), duOverlap_.data(), state_, fOverlap_.data()))
      return false;
  }
  layout_->exportAdd(fOverlap_.data(), df, 3);
  return true;
}

std::size_t Model::linearisationBytes() const {
  std::size_t bytes = yLinearised_.capacity() * sizeof(double);
  for (const auto& l : linearisations_)
    if (l) bytes += l->bytes();
  return bytes;
}

}  // namespace pf
