#pragma once
// Named per-node and per-bond state arrays that materials declare and the core owns. History fields keep
// a committed copy (step n) and a trial copy (step n+1): solvers commit after a converged load step and
// roll back otherwise, so every iteration of a step starts from the committed state.
#include <map>
#include <string>
#include <vector>

namespace pf {

enum class Location { Node, Bond };

struct StateSpec {
  std::string name;         // also the output variable name (Peridigm style, e.g. "Lambda")
  Location where = Location::Node;
  bool history = false;     // needs committed/trial pair
  bool output = false;      // may be requested in Output Variables
  double initial = 0.0;     // value of every entry (trial and committed) before the first step, e.g. 1 for
                            // a diagonal component of a tensor that starts as the identity
};

class StateStore {
 public:
  // numNodes: owned nodes; numBonds: bonds of the owned nodes.
  void allocate(const std::vector<StateSpec>& specs, int numNodes, std::size_t numBonds);

  bool has(const std::string& name) const { return fields_.count(name) != 0; }
  double* trial(const std::string& name);                 // the value being computed (n+1)
  const double* trial(const std::string& name) const;
  const double* committed(const std::string& name) const; // value at the last converged step (n)
  const StateSpec& spec(const std::string& name) const;
  std::vector<StateSpec> specs() const;

  // trial -> committed for every history field. The two arrays are swapped, not copied (a copy streamed
  // every per-bond history array once more per explicit step): afterwards trial holds stale values, so
  // a material must write every trial value of its history fields on each evaluation, from committed.
  void commit();
  void rollback();  // committed -> trial for every history field (a copy: trial is then valid)
  // A restart: where to write the committed values of history field `name` (as many as it has entries);
  // rollback() then copies them to trial. std::logic_error if the field keeps no history.
  double* restoreCommitted(const std::string& name);

 private:
  struct Field {
    StateSpec spec;
    std::vector<double> trial, committed;
  };
  Field& field(const std::string& name);
  const Field& field(const std::string& name) const;
  std::map<std::string, Field> fields_;
};

}  // namespace pf
