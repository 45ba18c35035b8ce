#pragma once
// Peridigm's "Diffusion": a block with heat conduction (materials/HeatConduction.hpp, conductivity `Coefficient`)
// and no force model, for the steady solves of ImplicitDiffusion. As a Material it carries no force and no
// stiffness; the mechanics solvers refuse a deck whose blocks all lack a force model (Solver's `Solve For
// Displacement`).
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"

namespace pf {

class DiffusionMaterial : public Material {
 public:
  explicit DiffusionMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  void computeForce(const FamilyView&, const double*, StateStore&, double*) const override {}
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  bool hasForceDerivative() const override { return true; }  // the zero force's derivative is zero
  bool forceDerivative(const FamilyView&, const double*, const double*, const StateStore&, double*) const override {
    return true;
  }
  bool hasForceModel() const override { return false; }
  double density() const override { return density_; }
  Dimension dimension() const override { return Dimension::ThreeD; }

 private:
  double density_ = 0.0;
};

}  // namespace pf
