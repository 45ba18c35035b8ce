#include "ElasticPlasticMaterial.hpp"

#include "core/InputError.hpp"
#include "OsbKernels.hpp"
#include "SolidParameters.hpp"

namespace pf {

ElasticPlasticMaterial::ElasticPlasticMaterial(const MaterialInput& in, bool hardening)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")) {
  params_.dim = dimensionFrom(in, &params_.thickness);
  params_.osb = osbConstants(params_.dim, moduli_);
  params_.yieldStress = in.get("Yield Stress");  // > 0: its spec's range, as every range below
  if (hardening) {
    if (in.has("Hardening Modulus") && in.has("Isotropic Hardening Modulus"))
      throw InputError(in.inputFile + ": material '" + in.name + "': give 'Isotropic Hardening Modulus' or "
                       "'Hardening Modulus' (Peridigm's name for it), not both");
    params_.isoHardening = in.get(in.has("Hardening Modulus") ? "Hardening Modulus" : "Isotropic Hardening Modulus");
    params_.kinHardening = in.get("Kinematic Hardening Modulus");
  }
  params_.norm = in.text("Yield Normalization") == "Continuum" ? YieldNormalization::Continuum
                                                                : YieldNormalization::Discrete;
}

std::vector<ParameterSpec> ElasticPlasticMaterial::parameters() {
  std::vector<ParameterSpec> params = elasticSolidParameters();
  params.push_back(ParameterSpec::real("Yield Stress", "initial uniaxial yield stress sigma_y0 [Pa]").need().positive());
  params.push_back(ParameterSpec::text("Yield Normalization",
                                       "'Discrete': yield constants from the node's weighted volume m; 'Continuum': "
                                       "the paper's 4 pi delta^5/5, pi h delta^4/2")
                       .oneOf({"Discrete", "Continuum"})
                       .byDefault("Discrete"));
  return params;
}

MaterialEntry ElasticPlasticMaterial::entry() {
  return {"Elastic Plastic", "OSB J2 elastic-perfectly plastic solid (Mitchell 2011)", parameters(),
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticPlasticMaterial(in, false)); },
          outputs()};
}

std::vector<std::string> ElasticPlasticMaterial::outputs() {
  std::vector<std::string> names;
  for (const StateSpec& s : states())
    if (s.output) names.push_back(s.name);
  return names;
}

std::vector<StateSpec> ElasticPlasticMaterial::stateSpecs() const { return states(); }

std::vector<StateSpec> ElasticPlasticMaterial::states() {
  return {{"Deviatoric_Plastic_Extension", Location::Bond, true, false},
          {"Lambda", Location::Node, true, true},
          {"Equivalent_Plastic_Strain", Location::Node, true, true},
          {"Back_Stress", Location::Node, true, true},
          {"Von_Mises_Sign", Location::Node, true, false},
          {"Von_Mises_Stress", Location::Node, false, true},
          {"Signed_Von_Mises_Stress", Location::Node, false, true},
          {"Dilatation", Location::Node, false, true},
          {"Return_Mapping_Iterations", Location::Node, false, false}};
}

void ElasticPlasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                          double* force) const {
  J2Fields f;
  f.edpN = state.committed("Deviatoric_Plastic_Extension");
  f.edp = state.trial("Deviatoric_Plastic_Extension");
  f.lambdaN = state.committed("Lambda");
  f.lambda = state.trial("Lambda");
  f.alphaN = state.committed("Equivalent_Plastic_Strain");
  f.alpha = state.trial("Equivalent_Plastic_Strain");
  f.qN = state.committed("Back_Stress");
  f.q = state.trial("Back_Stress");
  f.signN = state.committed("Von_Mises_Sign");
  f.sign = state.trial("Von_Mises_Sign");
  f.vonMises = state.trial("Von_Mises_Stress");
  f.signedVonMises = state.trial("Signed_Von_Mises_Stress");
  f.theta = state.trial("Dilatation");
  f.iterations = state.trial("Return_Mapping_Iterations");
  osbJ2Force(fam, params_, y, f, force);
}

void ElasticPlasticMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  // The elastic bound also bounds the plastic tangent (the return only softens the deviatoric part).
  osbStiffnessBound(fam, params_.osb, bound);
}

}  // namespace pf

namespace pf {
void ElasticPlasticMaterial::pairStiffness(const FamilyView& fam, double* c) const { osbPairStiffness(fam, params_.osb, c); }
}  // namespace pf
