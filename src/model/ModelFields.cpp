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

void Model::prepareFieldOperators() {
  const std::size_t no = static_cast<std::size_t>(layout_->numOverlap());
  for (const BlockModel& b : blocks_)
    for (const auto& op : b.fieldOperators) {
      const std::string name = op->nodeValueName();
      if (name.empty()) continue;
      std::vector<double>& values = operatorValueArrays_[name];
      values.resize(no, 0.0);
      op->nodeValue(blockView(b), values.data());  // the block's owned nodes
    }
  // Every rank takes part in each name's ghost exchange, also a rank that owns no node of the blocks behind it:
  // the names are agreed first (each rank's list broadcast in turn; once, at set-up).
  const Communicator& comm = layout_->comm();
  std::string mine;
  for (const auto& kv : operatorValueArrays_) mine += kv.first + "\n";
  for (int r = 0; r < comm.size(); ++r) {
    const std::string theirs = comm.broadcast(mine, r);
    for (std::size_t a = 0, b; (b = theirs.find('\n', a)) != std::string::npos; a = b + 1)
      operatorValueArrays_[theirs.substr(a, b - a)].resize(no, 0.0);
  }
  for (auto& kv : operatorValueArrays_) {
    std::vector<double> owned(kv.second.begin(), kv.second.begin() + numOwned());
    layout_->importToOverlap(owned.data(), kv.second.data(), 1);
    operatorValues_.entries.emplace_back(kv.first, kv.second.data());
  }
}

void Model::fieldRate(const std::string& field, const double* owned, double* rate) {
  fieldOverlap_.resize(static_cast<std::size_t>(layout_->numOverlap()));
  layout_->importToOverlap(owned, fieldOverlap_.data(), 1);
  std::fill(rate, rate + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    FamilyView v = view(b);
    v.fields = &operatorValues_;
    if (op.isLinear()) op.apply(v, fieldOverlap_.data(), rate);
  });
  if (fields_.has(field)) fields_.surface(field).addLinear(owned, rate);
}

void Model::fieldDiagonal(const std::string& field, double* diag) const {
  std::fill(diag, diag + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    FamilyView v = blockView(b);
    v.fields = &operatorValues_;
    if (op.isLinear()) op.diagonal(v, diag);
  });
  if (fields_.has(field)) fields_.surface(field).addDiagonal(diag);
}

void Model::fieldSurfaceSource(const std::string& field, double* source) const {
  std::fill(source, source + numOwned(), 0.0);
  if (fields_.has(field)) fields_.surface(field).addSource(time_, x_, source);
}

void Model::fieldCapacity(const std::string& field, double* capacity) const {
  std::fill(capacity, capacity + numOwned(), 0.0);
  // The terms of one block come from one Materials entry: their capacities agree (rho c) or are 0.
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    for (int i = b.begin; i < b.end; ++i) capacity[i] = std::max(capacity[i], op.capacity());
  });
}

bool Model::capacityEverywhere(const std::string& field) const {
  double missing = fields_.has(field) ? 0.0 : 1.0;
  if (missing == 0.0) {
    std::vector<double> c(static_cast<std::size_t>(numOwned()));
    fieldCapacity(field, c.data());
    for (double x : c) missing = x > 0.0 ? missing : 1.0;
  }
  return !(max(missing) > 0.0);
}

void Model::fieldSource(const std::string& field, double dt, double* source) const {
  std::fill(source, source + numOwned(), 0.0);
  forTerms(blocks_, field, [&](const BlockModel& b, const FieldOperator& op) {
    if (op.hasSource()) op.addSource(blockView(b), state_, dt, source);
  });
}

bool Model::hasOperator(const std::string& field) const {
  double mine = fields_.has(field) && fields_.surface(field).linear() ? 1.0 : 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator& op) { mine = op.isLinear() ? 1.0 : mine; });
  return max(mine) > 0.0;
}

bool Model::hasFieldSource(const std::string& field) const {
  double mine = fields_.has(field) && !fields_.surface(field).empty() ? 1.0 : 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator& op) { mine = op.hasSource() ? 1.0 : mine; });
  return max(mine) > 0.0;
}

bool Model::hasFieldTerms(const std::string& field) const {
  double mine = 0.0;
  forTerms(blocks_, field, [&](const BlockModel&, const FieldOperator&) { mine = 1.0; });
  return max(mine) > 0.0;
}

}  // namespace pf
