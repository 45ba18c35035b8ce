#include "ViscoplasticCorrespondenceMaterial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "CorrespondenceLawParameters.hpp"
#include "core/InputError.hpp"

namespace pf {

ViscoplasticCorrespondenceMaterial::ViscoplasticCorrespondenceMaterial(const MaterialInput& in)
    : CorrespondenceMaterial(in, "Viscoplastic Correspondence"),
      law_(fosterLawFrom(in)) {
  const char* names[] = {"Melting Temperature", "Reference Temperature", "Thermal Softening Exponent"};
  int given = 0;
  for (const char* n : names) given += in.has(n) ? 1 : 0;
  if (given == 0) return;
  if (given != 3)
    throw InputError(in.where() + ": thermal softening needs all of 'Melting Temperature', 'Reference Temperature' "
                                  "and 'Thermal Softening Exponent'");
  softens_ = true;
  melting_ = in.get("Melting Temperature");
  roomTemperature_ = in.get("Reference Temperature");
  softeningExponent_ = in.get("Thermal Softening Exponent");
  if (!(melting_ > roomTemperature_))
    throw InputError(in.where() + ": 'Melting Temperature' must exceed 'Reference Temperature'");
}

std::vector<std::string> ViscoplasticCorrespondenceMaterial::fieldsRead() const {
  std::vector<std::string> f = CorrespondenceMaterial::fieldsRead();
  if (softens_) f.push_back("Temperature");
  return f;
}

double ViscoplasticCorrespondenceMaterial::softening(double T) const {
  if (!softens_) return 1.0;
  const double star = std::min(1.0, std::max(0.0, (T - roomTemperature_) / (melting_ - roomTemperature_)));
  return 1.0 - std::pow(star, softeningExponent_);
}

MaterialEntry ViscoplasticCorrespondenceMaterial::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = commonParameters(RateRule::Midpoint);
  for (const ParameterSpec& p : fosterParameters()) params.push_back(p);
  params.push_back(P::real("Melting Temperature", "T_m [K] of the thermal softening factor 1 - T*^q, "
                                                  "T* = (T - T_r)/(T_m - T_r) (Johnson-Cook; reads Temperature)"));
  params.push_back(P::real("Reference Temperature", "T_r [K]: the temperature of the fitted flow stress (no "
                                                    "softening at or below it)"));
  params.push_back(P::real("Thermal Softening Exponent", "q of the thermal softening factor").positive());
  std::vector<std::string> outputs = commonOutputs();
  outputs.push_back("Equivalent_Plastic_Strain");
  outputs.push_back("Equivalent_Plastic_Strain_Rate");
  MaterialEntry e{"Viscoplastic Correspondence",
          "rate-dependent J2 correspondence solid (Foster, Silling & Chen 2010, Eqs. 49-61) with hourglass control",
          params,
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ViscoplasticCorrespondenceMaterial(in)); },
          outputs};
  e.createOperators = [](const MaterialInput& in) { return heatTerms(in, "Viscoplastic Correspondence"); };
  return e;
}

std::vector<StateSpec> ViscoplasticCorrespondenceMaterial::modelStateSpecs() const {
  // Viscoplastic_Time starts as NaN: "never committed", the step then starts at FamilyView::startTime. The
  // rate is history so that an evaluation without time passing (the output pass after a quasi-static
  // step's commit) reports the rate of the step that led to the state instead of 0.
  return {{"Equivalent_Plastic_Strain", Location::Node, true, true},
          {"Equivalent_Plastic_Strain_Rate", Location::Node, true, true},
          {"Viscoplastic_Time", Location::Node, true, false, std::numeric_limits<double>::quiet_NaN()}};
}

void ViscoplasticCorrespondenceMaterial::updateStress(const FamilyView& fam, StateStore& state,
                                                      const std::vector<Mat3>& tauN, const std::vector<Mat3>& de,
                                                      const std::vector<double>&, std::vector<Mat3>& tau) const {
  const double* epsN = state.committed("Equivalent_Plastic_Strain");
  const double* timeN = state.committed("Viscoplastic_Time");
  const double* rateN = state.committed("Equivalent_Plastic_Strain_Rate");
  double* eps = state.trial("Equivalent_Plastic_Strain");
  double* rate = state.trial("Equivalent_Plastic_Strain_Rate");
  double* time = state.trial("Viscoplastic_Time");
  const double* T = softens_ ? fam.fields->find("Temperature") : nullptr;  // per overlap node, owned first
  FosterLaw law = law_;
  for (std::size_t k = 0; k < tau.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    const double dt = fam.time - (std::isnan(timeN[i]) ? fam.startTime : timeN[i]);
    if (T) law.yield = law_.yield * softening(T[i]);
    const FosterStep s = fosterUpdate(law, moduli().bulk, moduli().shear, tauN[k], epsN[i], de[k], dt);
    tau[k] = s.tau, eps[i] = s.epsP, time[i] = fam.time;
    rate[i] = dt > 0.0 ? s.rate : rateN[i];
  }
}

}  // namespace pf
