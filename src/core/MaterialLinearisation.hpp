#pragma once
// A material's tangent kept at one point: update() linearises at deformed positions y with the committed state,
// apply() then gives Material::forceDerivative at that y along any dy without redoing the work that does not
// depend on dy (for the J2 models: the gather, the trial pass and the return mapping). Made per block by
// Material::makeLinearisation; the implicit solvers update it once per Newton point and apply it per Krylov product.
#include <cstddef>

#include "BondFamily.hpp"
#include "StateStore.hpp"

namespace pf {

class MaterialLinearisation {
 public:
  virtual ~MaterialLinearisation() = default;
  // False where the material cannot linearise at y (its update fails there); may write the bond-damage trial flags
  // the force's gather writes.
  virtual bool update(const FamilyView& fam, const double* y, const StateStore& state) = 0;
  // Adds dF along dy (3 per overlap node) at the y of the last update to dforce, with forceDerivative's two-ended
  // accumulation.
  virtual void apply(const FamilyView& fam, const double* dy, double* dforce) const = 0;
  virtual std::size_t bytes() const = 0;  // memory held
};

}  // namespace pf
