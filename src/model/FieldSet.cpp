#include "FieldSet.hpp"

#include <algorithm>
#include <stdexcept>

#include "parallel/DistributedLayout.hpp"

namespace pf {

namespace {
const std::string kChange = "_Change";
std::string changeOf(const std::string& name) { return name + kChange; }
std::string startOf(const std::string& name) { return name + "_Start"; }
}  // namespace

std::string FieldSet::fieldOf(const std::string& value) {
  const std::size_t n = kChange.size();
  const bool change = value.size() > n && value.compare(value.size() - n, n, kChange) == 0;
  return change ? value.substr(0, value.size() - n) : value;
}

FieldSet::Field* FieldSet::find(const std::string& name) {
  for (Field& f : fields_)
    if (f.name == name) return &f;
  return nullptr;
}
const FieldSet::Field* FieldSet::find(const std::string& name) const {
  for (const Field& f : fields_)
    if (f.name == name) return &f;
  return nullptr;
}
FieldSet::Field& FieldSet::get(const std::string& name) {
  if (Field* f = find(name)) return *f;
  throw std::logic_error("FieldSet: no field '" + name + "'");
}
const FieldSet::Field& FieldSet::get(const std::string& name) const {
  if (const Field* f = find(name)) return *f;
  throw std::logic_error("FieldSet: no field '" + name + "'");
}

void FieldSet::add(const std::string& name, StateStore& state, int numOwned, std::size_t numBonds) {
  if (has(name)) return;
  // History, all three: a rollback must restore the change with the value, and a restart the start value.
  state.allocate({{name, Location::Node, true, true},
                  {changeOf(name), Location::Node, true, true},
                  {startOf(name), Location::Node, true, false}},
                 numOwned, numBonds);
  Field f;
  f.name = name;
  f.mask.assign(static_cast<std::size_t>(numOwned), 0);
  fields_.push_back(std::move(f));
}

void FieldSet::addRate(const std::string& name, const std::string& rate, StateStore& state, int numOwned,
                       std::size_t numBonds) {
  state.allocate({{rate, Location::Node, false, true}}, numOwned, numBonds);
  get(name).rate = rate;
}

void FieldSet::addInitial(const std::string& name, NodalLoad load) { get(name).initial.push_back(std::move(load)); }

void FieldSet::addPrescribed(const std::string& name, NodalLoad load) {
  Field& f = get(name);
  for (int i : load.nodes) f.mask[i] = 1;
  f.prescribed.push_back(std::move(load));
}

void FieldSet::setSource(const std::string& name, std::shared_ptr<FieldSource> source) {
  Field& f = get(name);
  std::fill(f.mask.begin(), f.mask.end(), 1);
  f.source = std::move(source);
}

void FieldSet::start(double t0, const std::vector<double>& x, StateStore& state) {
  for (Field& f : fields_) {
    double* v = state.trial(f.name);
    for (const NodalLoad& l : f.initial) forEachLoadValue(l, x, t0, 1, [v](int k, double val) { v[k] = val; });
    for (const NodalLoad& l : f.prescribed) forEachLoadValue(l, x, t0, 1, [v](int k, double val) { v[k] = val; });
    if (f.source) f.source->valuesAt(t0, v);
    const std::size_t n = f.mask.size();
    std::copy(v, v + n, state.restoreCommitted(f.name));
    std::copy(v, v + n, state.trial(startOf(f.name)));
    std::copy(v, v + n, state.restoreCommitted(startOf(f.name)));
    std::fill(state.trial(changeOf(f.name)), state.trial(changeOf(f.name)) + n, 0.0);
    std::fill(state.restoreCommitted(changeOf(f.name)), state.restoreCommitted(changeOf(f.name)) + n, 0.0);
  }
}

void FieldSet::impose(double t, const std::vector<double>& x, StateStore& state, const DistributedLayout& layout) {
  values_.entries.clear();
  for (Field& f : fields_) {
    const std::size_t n = f.mask.size();
    double* v = state.trial(f.name);
    // A history field's trial copy is stale after a commit (StateStore::commit): rewrite it from the committed one.
    if (!f.solved) std::copy(state.committed(f.name), state.committed(f.name) + n, v);
    for (const NodalLoad& l : f.prescribed) forEachLoadValue(l, x, t, 1, [v](int k, double val) { v[k] = val; });
    if (f.source) f.source->valuesAt(t, v);
    const double* t0 = state.committed(startOf(f.name));
    std::copy(t0, t0 + n, state.trial(startOf(f.name)));
    double* change = state.trial(changeOf(f.name));
    for (std::size_t i = 0; i < n; ++i) change[i] = v[i] - t0[i];
    const std::size_t no = static_cast<std::size_t>(layout.numOverlap());
    f.overlap.resize(no);
    f.changeOverlap.resize(no);
    layout.importToOverlap(v, f.overlap.data(), 1);
    layout.importToOverlap(change, f.changeOverlap.data(), 1);
    values_.entries.emplace_back(f.name, f.overlap.data());
    values_.entries.emplace_back(changeOf(f.name), f.changeOverlap.data());
  }
}

void FieldSet::updateChange(const std::string& name, StateStore& state) const {
  const std::size_t n = get(name).mask.size();
  const double* v = state.trial(name);
  const double* t0 = state.committed(startOf(name));
  double* change = state.trial(changeOf(name));
  for (std::size_t i = 0; i < n; ++i) change[i] = v[i] - t0[i];
}

void FieldSet::afterCommit(StateStore& state) const {
  for (const Field& f : fields_)
    if (f.solved) std::copy(state.committed(f.name), state.committed(f.name) + f.mask.size(), state.trial(f.name));
}

std::vector<std::string> FieldSet::outputs() const {
  std::vector<std::string> out;
  for (const Field& f : fields_) {
    out.push_back(f.name);
    out.push_back(changeOf(f.name));
    if (!f.rate.empty()) out.push_back(f.rate);
  }
  return out;
}

}  // namespace pf
