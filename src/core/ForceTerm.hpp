#pragma once
// A force on the displacement field besides the blocks' materials, between points that need not share a bond
// (contact): it finds its own partners in the deformed configuration, reads positions and velocities, and gives a
// force density per owned node, which is also its node output. The model holds a list of them and sums them
// (Model::termForce); a solver sees that sum only, never which term it holds.
#include <string>

namespace pf {

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  // The node output its force density is written as (Peridigm's "Contact_Force_Density").
  virtual std::string outputName() const = 0;
  // Collective. f (3 per owned node, overwritten): its force density at step `step` of a run (0: the start; a
  // resumed run starts at its next step), time t, deformed positions y and velocities v (3 per owned node each).
  virtual void force(long step, double t, const double* y, const double* v, double* f) = 0;
};

}  // namespace pf
