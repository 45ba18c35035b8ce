#pragma once
// A force on the displacement field besides the blocks' materials, between points that need not share a bond
// (contact): it finds its own partners in the deformed configuration, reads positions and velocities, and gives a
// force density per owned node, which is also its node output. The model holds a list of them and sums them
// (Model::termForce); a solver sees that sum only, never which term it holds.
#include <string>
#include <vector>

namespace pf {

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  // The node output its force density is written as (Peridigm's "Contact_Force_Density").
  virtual std::string outputName() const = 0;
  // Collective. f (3 per owned node, overwritten): its force density at step `step` of a run (0: the start; a
  // resumed run starts at its next step), time t, deformed positions y and velocities v (3 per owned node each).
  virtual void force(long step, double t, const double* y, const double* v, double* f) = 0;
  // The energy it stores (J) over this rank's owned points at the last force() (contact: its penalty springs).
  virtual double storedEnergy() const { return 0.0; }
  // History columns of its own (the same names on every rank) and this rank's share of their values at the last
  // force(), which the caller sums over the ranks (contact: the force each block takes from each other block).
  virtual std::vector<std::string> historyNames() const { return {}; }
  virtual std::vector<double> historyShares() const { return {}; }
  // Collective: its deterministic work counts so far over all ranks, one line for the run's summary.
  virtual std::string workSummary() const { return ""; }
};

}  // namespace pf
