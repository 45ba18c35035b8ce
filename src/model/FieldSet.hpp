#pragma once
// The nodal scalar fields a model holds beside the displacement (today: Temperature), with their initial and
// prescribed conditions. A field's values live in the model's StateStore as node history, so commit, rollback,
// checkpoints and outputs treat it as any state; beside it `<name>_Change` (the value less its start value,
// Peridigm's Temperature_Change) and the start value itself. Before an evaluation at time t the trial values are
// the committed ones with t's prescribed conditions imposed, or, for a field a solver advances, the solver's own
// trial values with the prescribed ones imposed. The ghosted `<name>_Change` and `<name>` are what materials read
// (core/FieldValues.hpp).
#include <memory>
#include <string>
#include <vector>

#include "core/FieldValues.hpp"
#include "core/StateStore.hpp"
#include "model/FieldSource.hpp"
#include "model/FieldSurface.hpp"
#include "model/NodalLoad.hpp"

namespace pf {

class DistributedLayout;

class FieldSet {
 public:
  bool empty() const { return fields_.empty(); }
  bool has(const std::string& name) const { return find(name) != nullptr; }
  // The field a value materials read belongs to: "Temperature" for "Temperature" and "Temperature_Change".
  static std::string fieldOf(const std::string& value);
  // Declares the field (once; again is a no-op) and its state in `state` (numOwned nodes).
  void add(const std::string& name, StateStore& state, int numOwned, std::size_t numBonds);
  // The field's rate from its operators (core/FieldOperator.hpp) as the node output `rate` (Flux_Divergence),
  // written by whoever evaluates it at a reported state (FieldSet itself never does).
  void addRate(const std::string& name, const std::string& rate, StateStore& state, int numOwned, std::size_t numBonds);
  // The rate output's name of the field (addRate), or empty.
  const std::string& rateName(const std::string& name) const { return get(name).rate; }
  void addInitial(const std::string& name, NodalLoad load);
  void addPrescribed(const std::string& name, NodalLoad load);
  // The field's values at every node come from `source` (model/FieldSource.hpp), imposed after its prescribed
  // conditions wherever those are.
  void setSource(const std::string& name, std::shared_ptr<FieldSource> source);
  // A solver advances the field: impose() keeps its trial values except at prescribed nodes.
  void setSolved(const std::string& name) { get(name).solved = true; }
  // A solver wrote new trial values of the field: its trial `<name>_Change` (owned nodes) follows them. The ghosts
  // are left to the next impose (every evaluation starts with one), so a step's end does not exchange them twice.
  void updateChange(const std::string& name, StateStore& state) const;
  // After StateStore::commit (whose trial copies are then stale): a solved field's trial values = its committed ones,
  // where its solver's next step starts.
  void afterCommit(StateStore& state) const;
  // Per owned node: 1 where some prescribed condition of the field acts.
  const std::vector<char>& prescribedMask(const std::string& name) const { return get(name).mask; }
  const std::vector<NodalLoad>& prescribed(const std::string& name) const { return get(name).prescribed; }
  const std::vector<NodalLoad>& initial(const std::string& name) const { return get(name).initial; }
  // Its surface conditions (Heat Flux, Convection: model/FieldSurface.hpp).
  FieldSurface& surface(const std::string& name) { return get(name).surface; }
  const FieldSurface& surface(const std::string& name) const { return get(name).surface; }

  // The run's start at t0 (not a restart, whose values come from the checkpoint): the initial conditions,
  // then the prescribed ones of t0, as committed and trial values and as the start values. x: 3 per overlap node.
  void start(double t0, const std::vector<double>& x, StateStore& state);
  // Trial values for the evaluation at t, then their ghosts (collective).
  void impose(double t, const std::vector<double>& x, StateStore& state, const DistributedLayout& layout);
  // What materials read: `<name>` and `<name>_Change` per overlap node, as of the last impose.
  const FieldValues& values() const { return values_; }
  // The nodal output variables the fields provide (`<name>`, `<name>_Change`).
  std::vector<std::string> outputs() const;

 private:
  struct Field {
    std::string name;
    std::vector<NodalLoad> initial, prescribed;
    FieldSurface surface;
    std::string rate;  // its rate's output name, or empty
    std::vector<char> mask;
    std::shared_ptr<FieldSource> source;  // null: none
    bool solved = false;
    std::vector<double> owned, overlap, changeOverlap;  // staging and the ghosted values
  };
  std::vector<Field> fields_;
  FieldValues values_;
  Field* find(const std::string& name);
  const Field* find(const std::string& name) const;
  Field& get(const std::string& name);
  const Field& get(const std::string& name) const;
};

}  // namespace pf
