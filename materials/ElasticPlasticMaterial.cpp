#include "ElasticPlasticMaterial.hpp"

#include "core/InputError.hpp"
#include "OsbKernels.hpp"
#include "SolidParameters.hpp"

namespace pf {

namespace {

double nonNegative(const MaterialInput& in, const std::string& key) {
  const double v = in.get(key, 0.0);
  if (!(v >= 0.0))
    throw InputError(in.inputFile + ": material '" + in.name + "': '" + key + "' must be >= 0");
  return v;
}

}  // namespace

ElasticPlasticMaterial::ElasticPlasticMaterial(const MaterialInput& in, bool hardening)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")) {
  params_.dim = dimensionFrom(in, &params_.thickness);
  params_.osb = osbConstants(params_.dim, moduli_);
  const std::string where = in.inputFile + ": material '" + in.name + "'";
  params_.yieldStress = in.get("Yield Stress");
  if (!(params_.yieldStress > 0.0)) throw InputError(where + ": 'Yield Stress' must be positive");
  if (hardening) {
    if (in.has("Hardening Modulus") && in.has("Isotropic Hardening Modulus"))
      throw InputError(where + ": give 'Isotropic Hardening Modulus' or 'Hardening Modulus' (Peridigm's name "
                               "for it), not both");
    params_.isoHardening = in.has("Hardening Modulus") ? nonNegative(in, "Hardening Modulus")
                                                       : nonNegative(in, "Isotropic Hardening Modulus");
    params_.kinHardening = nonNegative(in, "Kinematic Hardening Modulus");
  }
  auto it = in.strings.find("Yield Normalization");
  if (it != in.strings.end()) {
    if (it->second == "Discrete") params_.norm = YieldNormalization::Discrete;
    else if (it->second == "Continuum") params_.norm = YieldNormalization::Continuum;
    else throw InputError(where + ": 'Yield Normalization' = '" + it->second + "' is not 'Discrete' or 'Continuum'");
  }
}

std::vector<ParameterSpec> ElasticPlasticMaterial::parameters() {
  using K = ParameterSpec::Kind;
  std::vector<ParameterSpec> params = elasticSolidParameters();
  params.push_back({"Yield Stress", K::Double, true, "initial uniaxial yield stress sigma_y0 [Pa]"});
  params.push_back({"Yield Normalization", K::String, false,
                    "'Discrete' (default: yield constants from the node's weighted volume m) or 'Continuum' "
                    "(the paper's 4 pi delta^5/5, pi h delta^4/2)"});
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
