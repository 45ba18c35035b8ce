#pragma once
// A term of a nodal scalar field's equation (core/FieldValues.hpp), e.g. heat conduction or plastic heating on
// Temperature, for the owned nodes of one block: a linear operator L(u) (conduction: the flux divergence, W/m^3)
// that gathers into its own nodes from the field's overlap values, and/or a source from the block's mechanical
// state over the last evaluated step (plastic work to heat), and the field's capacity per volume. It knows nothing
// of MPI, files or solvers. Built from a "Materials" entry (MaterialEntry::createOperators) the way a force model
// is, one instance per block.
#include <string>
#include <vector>

#include "BondFamily.hpp"
#include "StateStore.hpp"

namespace pf {

class FieldOperator {
 public:
  virtual ~FieldOperator() = default;
  // The field it acts on ("Temperature").
  virtual std::string field() const = 0;
  // Whether it has a linear part L (apply, diagonal); a pure source or capacity has none.
  virtual bool isLinear() const { return true; }
  // out[i] += L(u)_i for owned nodes i in [fam.begin, fam.end); u: one value per overlap node.
  virtual void apply(const FamilyView&, const double*, double*) const {}
  // diag[i] += |dL(u)_i / du_i| (the sum of its bonds' coefficients): the Jacobi preconditioner of an implicit
  // solve and, over the capacity, the explicit stable step.
  virtual void diagonal(const FamilyView&, double*) const {}
  // A per-node value of its own, from the node's family, that its bonds need at both ends (the family-normalised
  // conduction's family sum, for a bond constant symmetric in i and j): its name ("" = none) and its values for the
  // owned nodes. The model computes it once, ghosts it and hands it to apply and diagonal in FamilyView::fields under
  // that name.
  virtual std::string nodeValueName() const { return ""; }
  virtual void nodeValue(const FamilyView&, double* /*owned*/) const {}
  // The field's capacity per volume (rho c, J/(m^3 K)) for a transient solve; 0: the operator has none (Peridigm's
  // Diffusion, steady solves only).
  virtual double capacity() const { return 0.0; }
  // Whether it has a source (addSource).
  virtual bool hasSource() const { return false; }
  // out[i] += the source per volume and time (W/m^3) over the last evaluated step of length dt: from the block's
  // trial state less its committed state (owned nodes of the block).
  virtual void addSource(const FamilyView&, const StateStore&, double /*dt*/, double* /*out*/) const {}
  // The material outputs the source reads from the state; the model asks the block's material to compute them
  // (Material::enableOutput).
  virtual std::vector<std::string> materialOutputsRead() const { return {}; }
};

}  // namespace pf
