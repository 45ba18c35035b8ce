#pragma once
// "Pals": Peridigm's position-aware linear solid (Mitchell, Silling & Littlewood, J. Mech. Mater. Struct. 10 (2015);
// Peridigm_Pals_Model.cpp, pals.cxx), 3D. Each point X has its own influence functions omega, sigma
// (materials/PalsInfluence.hpp), fixed on the reference family; with e = |Y| - |z| the extension of bond z:
//   theta = sum_j omega |z| e V_j,   m = sum_j sigma |z|^2 V_j,
//   p = (K + 2 mu m / 9) theta - (2 mu / 3) sum_j sigma |z| e V_j,
//   t = p omega |z| + 2 mu sigma (e - theta |z| / 3),   f_i += t Y/|Y| V_j,  f_j -= t Y/|Y| V_i,
//   W = K theta^2 / 2 + mu sum_j sigma (e - theta |z| / 3)^2 V_j  (Stored_Elastic_Energy_Density).
// A broken bond (Critical Stretch damage) carries no force and leaves theta, p and W (m keeps its reference value), where
// Peridigm's model ignores bond damage.
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "core/ElasticModuli.hpp"
#include "core/InfluenceFunction.hpp"

namespace pf {

class PalsMaterial : public Material {
 public:
  explicit PalsMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  // Exact: the derivative of the force state above along dy, with the multipliers and m fixed (reference quantities).
  bool hasForceDerivative() const override { return true; }
  bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                       double* dforce) const override;
  bool breaksBonds() const override { return true; }  // computeForce calls breakBond per bond
  double density() const override { return density_; }
  Dimension dimension() const override { return Dimension::ThreeD; }

 private:
  ElasticModuli moduli_;
  double density_;
  Influence omega0_, sigma0_;  // the base functions: Dilatation / Deviatoric Influence Function
};

}  // namespace pf
