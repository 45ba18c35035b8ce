#pragma once
// An operator on a nodal scalar field (core/FieldValues.hpp), e.g. heat conduction on Temperature: from the
// field's values on the overlap nodes it adds the field's rate term to the owned nodes of one block (conduction:
// the flux divergence, W/m^3). It is linear in the field, gathers into its own nodes only (no reaction sent to a
// neighbour), and knows nothing of MPI, files or solvers. Built from a "Materials" entry (MaterialEntry::
// createOperator) the way a force model is, one instance per block.
#include <string>

#include "BondFamily.hpp"

namespace pf {

class FieldOperator {
 public:
  virtual ~FieldOperator() = default;
  // The field it acts on ("Temperature").
  virtual std::string field() const = 0;
  // out[i] += L(u)_i for owned nodes i in [fam.begin, fam.end); u: one value per overlap node.
  virtual void apply(const FamilyView& fam, const double* u, double* out) const = 0;
  // diag[i] += |dL(u)_i / du_i| (the sum of its bonds' coefficients): the Jacobi preconditioner of an implicit
  // solve and, over the capacity, the explicit stable step.
  virtual void diagonal(const FamilyView& fam, double* diag) const = 0;
  // The field's capacity per volume (rho c, J/(m^3 K)) for a transient solve; 0: the operator has none (Peridigm's
  // Diffusion, steady solves only).
  virtual double capacity() const { return 0.0; }
};

}  // namespace pf
