#include "StateStore.hpp"

#include <stdexcept>

namespace pf {

void StateStore::allocate(const std::vector<StateSpec>& specs, int numNodes, std::size_t numBonds) {
  for (const StateSpec& s : specs) {
    const std::size_t n = s.where == Location::Node ? static_cast<std::size_t>(numNodes) : numBonds;
    auto it = fields_.find(s.name);
    if (it != fields_.end()) {
      // Two blocks may declare the same field; they share one array over all owned nodes/bonds.
      if (it->second.spec.where != s.where) throw std::logic_error("state field '" + s.name + "' declared twice with different locations");
      it->second.spec.history = it->second.spec.history || s.history;
      it->second.spec.output = it->second.spec.output || s.output;
      if (it->second.spec.history && it->second.committed.empty()) it->second.committed.assign(n, it->second.spec.initial);
      continue;
    }
    Field f;
    f.spec = s;
    f.trial.assign(n, s.initial);
    if (s.history) f.committed.assign(n, s.initial);
    fields_.emplace(s.name, std::move(f));
  }
}

StateStore::Field& StateStore::field(const std::string& name) {
  auto it = fields_.find(name);
  if (it == fields_.end()) throw std::logic_error("state field '" + name + "' was not declared");
  return it->second;
}
const StateStore::Field& StateStore::field(const std::string& name) const {
  auto it = fields_.find(name);
  if (it == fields_.end()) throw std::logic_error("state field '" + name + "' was not declared");
  return it->second;
}

double* StateStore::trial(const std::string& name) { return field(name).trial.data(); }
const double* StateStore::trial(const std::string& name) const { return field(name).trial.data(); }

const double* StateStore::committed(const std::string& name) const {
  const Field& f = field(name);
  return f.spec.history ? f.committed.data() : f.trial.data();
}

const StateSpec& StateStore::spec(const std::string& name) const { return field(name).spec; }

std::vector<StateSpec> StateStore::specs() const {
  std::vector<StateSpec> out;
  for (const auto& kv : fields_) out.push_back(kv.second.spec);
  return out;
}

void StateStore::commit() {
  for (auto& kv : fields_)
    if (kv.second.spec.history) kv.second.committed.swap(kv.second.trial);
}

void StateStore::rollback() {
  for (auto& kv : fields_)
    if (kv.second.spec.history) kv.second.trial = kv.second.committed;
}

double* StateStore::restoreCommitted(const std::string& name) {
  Field& f = field(name);
  if (!f.spec.history) throw std::logic_error("state field '" + name + "' keeps no history to restore");
  return f.committed.data();
}

}  // namespace pf
