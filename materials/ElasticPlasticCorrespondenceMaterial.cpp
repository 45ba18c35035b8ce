#include "ElasticPlasticCorrespondenceMaterial.hpp"

#include <cmath>

#include "CorrespondenceLawParameters.hpp"
#include "core/InputError.hpp"

namespace pf {

namespace {

using Law = ElasticPlasticCorrespondenceMaterial::Law;
const char* const kPlastic = "Elastic Plastic Correspondence";
const char* const kHardening = "Isotropic Hardening Correspondence";
const char* const kNeedleman = "Viscoplastic Needleman Correspondence";
const char* const kFlawParameters[] = {"Flaw Location X", "Flaw Location Y", "Flaw Location Z", "Flaw Size",
                                       "Flaw Magnitude"};

const char* modelName(Law law) {
  return law == Law::Perfect ? kPlastic : law == Law::LinearHardening ? kHardening : kNeedleman;
}

const char* summary(Law law) {
  switch (law) {
    case Law::Perfect:
      return "Peridigm's elastic perfectly plastic J2 correspondence solid (radial return in the unrotated frame) "
             "with hourglass control";
    case Law::LinearHardening:
      return "Peridigm's J2 correspondence solid with linear isotropic hardening (radial return in the unrotated "
             "frame) and hourglass control";
    case Law::Needleman:
      break;
  }
  return "Peridigm's J2 correspondence solid with Needleman's rate-dependent hardening Y (1 + eps_p/e0)^n / (1 + "
         "(eps_p/e1)^2) (eps_p' / r0)^m (bisection for the multiplier, as Peridigm) and hourglass control";
}

void addLawParameters(Law law, std::vector<ParameterSpec>& params) {
  using P = ParameterSpec;
  for (const ParameterSpec& p : peridigmJ2Parameters(law == Law::LinearHardening)) params.push_back(p);
  if (law != Law::Needleman) return;
  params.push_back(P::real("Strain Hardening Exponent", "n, of (1 + eps_p/e0)^n").need().nonNegative());
  params.push_back(P::real("Rate Hardening Exponent", "m, of (eps_p' / r0)^m").need().nonNegative());
  params.push_back(P::real("Reference Strain Rate", "r0 [1/s]").need().positive());
  params.push_back(P::real("Reference Strain 0", "e0, the strain scale of the hardening").need().positive());
  params.push_back(P::real("Reference Strain 1", "e1, the strain scale of the softening 1/(1 + (eps_p/e1)^2)")
                       .need().positive());
}

MaterialEntry entryOf(Law law) {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = CorrespondenceMaterial::commonParameters(CorrespondenceMaterial::RateRule::EndOfStep);
  addLawParameters(law, params);
  if (law != Law::Perfect) {
    params.push_back(P::flag("Enable Flaw", "Peridigm's flaw: Y(x) = Y (1 - m exp(-|x - x_f|^2 / s^2)); "
                                            "given (true or false), all five Flaw parameters are needed"));
    params.push_back(P::real("Flaw Location X", "x_f [m]"));
    params.push_back(P::real("Flaw Location Y", "y_f [m]"));
    params.push_back(P::real("Flaw Location Z", "z_f [m]"));
    params.push_back(P::real("Flaw Size", "s [m], the flaw's radius of decay").positive());
    params.push_back(P::real("Flaw Magnitude", "m, the relative reduction of Y at the flaw's centre").below(1.0));
  }
  std::vector<std::string> outputs = CorrespondenceMaterial::commonOutputs();
  outputs.push_back("Equivalent_Plastic_Strain");
  const char* model = modelName(law);
  MaterialEntry e{model, summary(law), params,
                  [law](const MaterialInput& in) {
                    return std::unique_ptr<Material>(new ElasticPlasticCorrespondenceMaterial(in, law));
                  },
                  outputs};
  e.createOperators = [model](const MaterialInput& in) { return CorrespondenceMaterial::heatTerms(in, model); };
  return e;
}

}  // namespace

MaterialEntry ElasticPlasticCorrespondenceMaterial::entry() { return entryOf(Law::Perfect); }
MaterialEntry ElasticPlasticCorrespondenceMaterial::hardeningEntry() { return entryOf(Law::LinearHardening); }
MaterialEntry ElasticPlasticCorrespondenceMaterial::needlemanEntry() { return entryOf(Law::Needleman); }

ElasticPlasticCorrespondenceMaterial::ElasticPlasticCorrespondenceMaterial(const MaterialInput& in, Law law)
    : CorrespondenceMaterial(in, modelName(law)), law_(law), yield_(in.get("Yield Stress")) {
  if (law == Law::Perfect) return;
  if (law == Law::LinearHardening) modulus_ = in.get("Hardening Modulus");
  if (law == Law::Needleman) {
    needleman_.n = in.get("Strain Hardening Exponent");
    needleman_.m = in.get("Rate Hardening Exponent");
    needleman_.rate0 = in.get("Reference Strain Rate");
    needleman_.e0 = in.get("Reference Strain 0");
    needleman_.e1 = in.get("Reference Strain 1");
  }
  // As Peridigm: "Enable Flaw" given (either value) reads all five; without it they would be ignored, an error here.
  int given = 0;
  for (const char* n : kFlawParameters) given += in.has(n) ? 1 : 0;
  if (!in.has("Enable Flaw")) {
    if (given > 0) throw InputError(in.where() + ": the Flaw parameters need 'Enable Flaw' = true");
    return;
  }
  if (given != 5)
    throw InputError(in.where() + ": 'Enable Flaw' needs all of 'Flaw Location X', 'Flaw Location Y', "
                                  "'Flaw Location Z', 'Flaw Size', 'Flaw Magnitude'");
  flaw_ = in.flag("Enable Flaw");
  for (int a = 0; a < 3; ++a) flawAt_[a] = in.get(kFlawParameters[a]);
  flawSize_ = in.get("Flaw Size");
  flawMagnitude_ = in.get("Flaw Magnitude");
}

double ElasticPlasticCorrespondenceMaterial::yieldStressAt(const double* x) const {
  if (!flaw_) return yield_;
  double r2 = 0.0;
  for (int a = 0; a < 3; ++a) r2 += (x[a] - flawAt_[a]) * (x[a] - flawAt_[a]);
  return yield_ * (1.0 - flawMagnitude_ * std::exp(-r2 / (flawSize_ * flawSize_)));
}

std::vector<StateSpec> ElasticPlasticCorrespondenceMaterial::modelStateSpecs() const {
  return {{"Equivalent_Plastic_Strain", Location::Node, true, true}};
}

void ElasticPlasticCorrespondenceMaterial::updateStress(const FamilyView& fam, StateStore& state,
                                                        const std::vector<Mat3>& tauN, const std::vector<Mat3>& de,
                                                        const std::vector<double>& dt, std::vector<Mat3>& tau) const {
  const double* epsN = state.committed("Equivalent_Plastic_Strain");
  double* eps = state.trial("Equivalent_Plastic_Strain");
  const double K = moduli().bulk, G = moduli().shear;
  for (std::size_t k = 0; k < tau.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    const double Y = yieldStressAt(fam.x + 3 * i);
    const PeridigmJ2Step s =
        law_ == Law::Perfect           ? peridigmPerfectPlastic(tauN[k], de[k], epsN[i], K, G, Y)
        : law_ == Law::LinearHardening ? peridigmIsotropicHardening(tauN[k], de[k], epsN[i], K, G, Y, modulus_)
                                       : peridigmNeedleman(tauN[k], de[k], epsN[i], K, G, Y, needleman_, dt[k]);
    tau[k] = s.tau, eps[i] = s.eqps;
  }
}

}  // namespace pf
