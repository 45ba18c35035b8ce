#include "ElasticPlasticCorrespondenceMaterial.hpp"

#include <cmath>

#include "core/InputError.hpp"
#include "PeridigmJ2Update.hpp"

namespace pf {

namespace {

const char* const kPlastic = "Elastic Plastic Correspondence";
const char* const kHardening = "Isotropic Hardening Correspondence";
const char* const kFlawParameters[] = {"Flaw Location X", "Flaw Location Y", "Flaw Location Z", "Flaw Size",
                                       "Flaw Magnitude"};

MaterialEntry entryOf(bool hardening) {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = CorrespondenceMaterial::commonParameters(CorrespondenceMaterial::RateRule::EndOfStep);
  params.push_back(P::real("Yield Stress", "Y, the initial yield stress [Pa]").need().positive());
  if (hardening) {
    params.push_back(P::real("Hardening Modulus", "H [Pa]: the yield stress is Y + H eps_p").need());
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
  const char* model = hardening ? kHardening : kPlastic;
  MaterialEntry e{model,
                  hardening ? "Peridigm's J2 correspondence solid with linear isotropic hardening (radial return in "
                              "the unrotated frame) and hourglass control"
                            : "Peridigm's elastic perfectly plastic J2 correspondence solid (radial return in the "
                              "unrotated frame) with hourglass control",
                  params,
                  [hardening](const MaterialInput& in) {
                    return std::unique_ptr<Material>(new ElasticPlasticCorrespondenceMaterial(in, hardening));
                  },
                  outputs};
  e.createOperators = [model](const MaterialInput& in) { return CorrespondenceMaterial::heatTerms(in, model); };
  return e;
}

}  // namespace

MaterialEntry ElasticPlasticCorrespondenceMaterial::entry() { return entryOf(false); }
MaterialEntry ElasticPlasticCorrespondenceMaterial::hardeningEntry() { return entryOf(true); }

ElasticPlasticCorrespondenceMaterial::ElasticPlasticCorrespondenceMaterial(const MaterialInput& in, bool hardening)
    : CorrespondenceMaterial(in, hardening ? kHardening : kPlastic), hardening_(hardening),
      yield_(in.get("Yield Stress")) {
  if (!hardening) return;
  modulus_ = in.get("Hardening Modulus");
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
                                                        std::vector<Mat3>& tau) const {
  const double* epsN = state.committed("Equivalent_Plastic_Strain");
  double* eps = state.trial("Equivalent_Plastic_Strain");
  const double K = moduli().bulk, G = moduli().shear;
  for (std::size_t k = 0; k < tau.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    const PeridigmJ2Step s =
        hardening_ ? peridigmIsotropicHardening(tauN[k], de[k], epsN[i], K, G, yieldStressAt(fam.x + 3 * i), modulus_)
                   : peridigmPerfectPlastic(tauN[k], de[k], epsN[i], K, G, yield_);
    tau[k] = s.tau, eps[i] = s.eqps;
  }
}

}  // namespace pf
