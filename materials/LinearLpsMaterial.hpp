#pragma once
// "Linear LPS Partial Volume": Peridigm's linearised linear peridynamic solid (Peridigm_LinearLPSPVMaterial.cpp), 3D
// only. The force is linear in the displacement u = y - x, along the reference bond xi (small-displacement theory):
//   theta_i = (3/m_i) sum_j omega (xi . eta) V_j,   eta = u_j - u_i
//   f_ij    = (9K - 15G) omega theta_i / (3 m_i) xi + 15G omega (xi . eta) / (m_i |xi|^2) xi,
// f_i += f_ij V_j, f_j -= f_ij V_i: the derivative of "Elastic" at the reference configuration (docs/materials.md).
// The tangent is the force itself applied to du, so the implicit solvers converge in one Newton step.
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "OsbConstants.hpp"

namespace pf {

class LinearLpsMaterial : public Material {
 public:
  explicit LinearLpsMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  bool hasForceDerivative() const override { return true; }
  bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                       double* dforce) const override;
  double density() const override { return density_; }
  Dimension dimension() const override { return Dimension::ThreeD; }

 private:
  ElasticModuli moduli_;
  double density_;
  OsbConstants osb_;  // the 3D constants of "Elastic": its stiffness bound and pair stiffness at y = x are this model's
};

}  // namespace pf
