// The Model's field terms (core/FieldOperator.hpp): the blocks' operators and sources on a field beside the
// displacement, summed per owned node.
#include <algorithm>

#include "Model.hpp"

namespace pf {

namespace {
// Calls f(block, term) for every term of every block on `field`.
template <class F>
void forTerms(const std::vector<BlockModel>& blocks, const std::string& field, F&& f) {
  for (const BlockModel& b : blocks)
    for (const auto& op : b.fieldOperators)
      if (op->field() == field) f(b, *op);
}
}  // namespace

void Model::fieldRate(const std::string& field, const double* owned, double* rate) {
  fieldOverlap_.resize(static_cast<std::size_t>(layout_->numOverlap()));
  layout_->importToOverlap(owned, fieldOverlap_.data(), 1);
  std::fill(rate, rate + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    if (op.isLinear()) op.apply(view(b), fieldOverlap_.data(), rate);
  });
}

void Model::fieldDiagonal(const std::string& field, double* diag) const {
  std::fill(diag, diag + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    if (op.isLinear()) op.diagonal(blockView(b), diag);
  });
}

void Model::fieldCapacity(const std::string& field, double* capacity) const {
  std::fill(capacity, capacity + numOwned(), 0.0);
  // The terms of one block come from one Materials entry: their capacities agree (rho c) or are 0.
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    for (int i = b.begin; i < b.end; ++i) capacity[i] = std::max(capacity[i], op.capacity());
  });
}

void Model::fieldSource(const std::string& field, double dt, double* source) const {
  std::fill(source, source + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    if (op.hasSource()) op.addSource(blockView(b), state_, dt, source);
  });
}

bool Model::hasOperator(const std::string& field) const {
  double mine = 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator& op) { mine = op.isLinear() ? 1.0 : mine; });
  return max(mine) > 0.0;
}

bool Model::hasFieldSource(const std::string& field) const {
  double mine = 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator& op) { mine = op.hasSource() ? 1.0 : mine; });
  return max(mine) > 0.0;
}

bool Model::hasFieldTerms(const std::string& field) const {
  double mine = 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator&) { mine = 1.0; });
  return max(mine) > 0.0;
}

}  // namespace pf
