#pragma once
// "Elastic": the linear ordinary state-based peridynamic solid (Silling et al. 2007; Pirzadeh et al.
// 2024 Eqs. 3-13) in 3D, plane stress and plane strain. Declares the node field Dilatation and, in 3D,
// Stored_Elastic_Energy = V_i W_i with Peridigm's energy density W = kappa theta^2/2 + (15 mu/(2 m))
// sum omega e^d e^d V_j (computed in an extra bond pass only once an output asks for it). With a Thermal
// Expansion Coefficient it reads Temperature_Change and subtracts the free thermal extension of each bond
// (materials/OsbThermalKernels.hpp).
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "OsbConstants.hpp"

namespace pf {

class ElasticMaterial : public Material {
 public:
  explicit ElasticMaterial(const MaterialInput& in);
  static MaterialEntry entry();
  // "Elastic Partial Volume": Peridigm's name for the same solid where its partial volumes come from
  // element-horizon intersections; without them (Periforge computes none) its force is Elastic's.
  static MaterialEntry partialVolumeEntry();

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  // Exact with thermal expansion too: the thermal stretch shifts the extension, not its derivative.
  bool hasForceDerivative() const override { return true; }
  bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                       double* dforce) const override;
  void enableOutput(const std::string& name) const override;
  bool breaksBonds() const override { return true; }  // every kernel drops broken bonds (BondDamage.hpp)
  std::vector<std::string> fieldsRead() const override;
  double density() const override { return density_; }
  Dimension dimension() const override { return dim_; }

  const ElasticModuli& moduli() const { return moduli_; }
  const OsbConstants& constants() const { return osb_; }
  double thickness() const { return thickness_; }

 private:
  ElasticModuli moduli_;
  double thickness_ = 0.0;  // before dim_: dim_'s initialiser (dimensionFrom) writes it
  Dimension dim_;
  double density_;
  OsbConstants osb_;
  // Thermal Expansion Coefficient times the plane-strain factor (materials/OsbThermalKernels.hpp); 0: none.
  double thermalCoefficient_ = 0.0;
  mutable bool energyWanted_ = false;  // set by enableOutput("Stored_Elastic_Energy") before the run
  mutable bool densityWanted_ = false;  // enableOutput("Stored_Elastic_Energy_Density"): W_i = energy / V_i as well
};

}  // namespace pf
