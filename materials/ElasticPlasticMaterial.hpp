#pragma once
// "Elastic Plastic": ordinary state-based J2 plasticity (Mitchell 2011; Pirzadeh et al. 2024) in 3D,
// plane stress and plane strain. The same class carries linear isotropic/kinematic hardening and serves
// "Elastic Plastic Hardening" (HardeningPlasticity.hpp); with K = H = 0 it is Mitchell's perfect plasticity.
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "OsbPlasticKernels.hpp"

namespace pf {

class ElasticPlasticMaterial : public Material {
 public:
  // hardening: read "Isotropic/Kinematic Hardening Modulus" (or Peridigm's "Hardening Modulus" as K).
  ElasticPlasticMaterial(const MaterialInput& in, bool hardening);
  static MaterialEntry entry();
  // Parameters of "Elastic Plastic" (elasticSolidParameters() + Yield Stress + Yield Normalization).
  static std::vector<ParameterSpec> parameters();
  static std::vector<StateSpec> states();          // what stateSpecs() returns (the same for every input)
  static std::vector<std::string> outputs();       // the output fields among them

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  double density() const override { return density_; }
  Dimension dimension() const override { return params_.dim; }

  const J2Parameters& j2() const { return params_; }
  const ElasticModuli& moduli() const { return moduli_; }

 private:
  ElasticModuli moduli_;
  double density_;
  J2Parameters params_;
};

}  // namespace pf
