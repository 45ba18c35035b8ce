#pragma once
// "Elastic Plastic": ordinary state-based J2 plasticity (Mitchell 2011; Pirzadeh et al. 2024) in 3D,
// plane stress and plane strain. The same class carries linear isotropic/kinematic hardening and serves
// "Elastic Plastic Hardening" (HardeningPlasticity.hpp); with K = H = 0 it is Mitchell's perfect plasticity.
// With a Thermal Expansion Coefficient it reads Temperature_Change and the plastic flow sees the mechanical
// extension only (J2Thermal, OsbPlasticKernels.hpp; docs/thermal.md).
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "OsbPlasticKernels.hpp"

namespace pf {

class ElasticPlasticMaterial : public Material {
 public:
  // hardening: Peridigm's "Hardening Modulus" H (its law, 3D) or the paper's "Isotropic/Kinematic Hardening
  // Modulus" K, H (InputError if both kinds are given), and Peridigm's shear correction factor.
  ElasticPlasticMaterial(const MaterialInput& in, bool hardening);
  static MaterialEntry entry();
  // elasticSolidParameters() + Yield Stress + Yield Normalization; hardening: the shear correction as in
  // Peridigm's Elastic Plastic Hardening (the hardening moduli are added by HardeningPlasticity). Both entries
  // append the thermal ones (withThermalExpansion).
  static std::vector<ParameterSpec> parameters(bool hardening);
  // Its terms on Temperature (SolidParameters.hpp heatTermsOf: conduction with "Thermal Conductivity");
  // MaterialEntry::createOperators of both entries.
  static std::vector<std::unique_ptr<FieldOperator>> heatTerms(const MaterialInput& in);
  static std::vector<StateSpec> states();          // what stateSpecs() returns (the same for every input)
  static std::vector<std::string> outputs();       // the output fields among them

  std::vector<StateSpec> stateSpecs() const override;  // states(), and Stored_Elastic_Energy in 3D
  void enableOutput(const std::string& name) const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  // The consistent tangent of the return mapping (OsbPlasticTangent.hpp), or the elastic one with plasticity
  // disabled. Reads the committed history, as the force does. With thermal expansion the implicit solvers
  // differentiate numerically (the thermal kernels have no tangent yet), as for "Elastic".
  bool hasForceDerivative() const override { return alpha_ == 0.0; }
  bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                       double* dforce) const override;
  // The same tangent kept per Newton point (OsbPlasticTangent.hpp J2Tangent: the return per node).
  std::unique_ptr<MaterialLinearisation> makeLinearisation() const override;
  bool breaksBonds() const override { return true; }  // every kernel drops broken bonds (BondDamage.hpp)
  std::vector<std::string> fieldsRead() const override;  // Temperature_Change with thermal expansion
  double density() const override { return density_; }
  Dimension dimension() const override { return params_.dim; }

  const J2Parameters& j2() const { return params_; }
  const ElasticModuli& moduli() const { return moduli_; }
  bool shearCorrection() const { return shearCorrection_; }

 private:
  ElasticModuli moduli_;
  double density_;
  J2Parameters params_;
  bool shearCorrection_ = false;
  bool disablePlasticity_ = false;  // Peridigm's "Disable Plasticity" (Elastic Plastic only): elastic kernel
  double alpha_ = 0.0;              // Thermal Expansion Coefficient; 0: none
  J2Thermal thermal_;                // its coefficients in the J2 kernel
  double elasticThermal_ = 0.0;      // and in the elastic one (Disable Plasticity): thermalExpansionOf
  mutable bool energyWanted_ = false;  // set by enableOutput("Stored_Elastic_Energy") before the run
};

}  // namespace pf
