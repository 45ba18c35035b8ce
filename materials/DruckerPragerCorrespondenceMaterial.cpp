#include "DruckerPragerCorrespondenceMaterial.hpp"

#include "CorrespondenceLawParameters.hpp"

namespace pf {

DruckerPragerCorrespondenceMaterial::DruckerPragerCorrespondenceMaterial(const MaterialInput& in)
    : CorrespondenceMaterial(in, "Drucker Prager Correspondence"),
      law_(druckerPragerLawFrom(in)) {}

MaterialEntry DruckerPragerCorrespondenceMaterial::entry() {
  std::vector<ParameterSpec> params = commonParameters(RateRule::Midpoint);
  for (const ParameterSpec& p : druckerPragerParameters()) params.push_back(p);
  std::vector<std::string> outputs = commonOutputs();
  outputs.push_back("Mean_Stress");
  outputs.push_back("Equivalent_Plastic_Strain");
  outputs.push_back("Hardening_Parameter");
  outputs.push_back("Yield_Function");
  MaterialEntry e{"Drucker Prager Correspondence",
          "Drucker-Prager correspondence solid, hyperbolic hardening, non-associated flow (Li & Geng, Eqs. 38-48, "
          "A1-A18) with hourglass control",
          params,
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new DruckerPragerCorrespondenceMaterial(in)); },
          outputs};
  e.createOperators = [](const MaterialInput& in) { return heatTerms(in, "Drucker Prager Correspondence"); };
  return e;
}

std::vector<StateSpec> DruckerPragerCorrespondenceMaterial::modelStateSpecs() const {
  // Equivalent_Plastic_Strain is the paper's PIV xi (Eq. 47, A13), the history; m and the mean stress
  // follow from it and the stress, written for output only. Hardening_Parameter starts at m0.
  return {{"Equivalent_Plastic_Strain", Location::Node, true, true},
          {"Hardening_Parameter", Location::Node, false, true, law_.m0},
          {"Mean_Stress", Location::Node, false, true},
          // druckerPragerYieldRatio of the evaluated state. History only so that the committed copy (what output
          // writes) is the value of the committed evaluation, not of the core's re-evaluation after the commit
          // (which would return-map a loading-balance round's points held elastic within its tolerance).
          {"Yield_Function", Location::Node, true, true}};
}

void DruckerPragerCorrespondenceMaterial::updateStress(const FamilyView& fam, StateStore& state,
                                                       const std::vector<Mat3>& tauN, const std::vector<Mat3>& de,
                                                       const std::vector<double>&, std::vector<Mat3>& tau) const {
  const double* xiN = state.committed("Equivalent_Plastic_Strain");
  double* xi = state.trial("Equivalent_Plastic_Strain");
  double* m = state.trial("Hardening_Parameter");
  double* mean = state.trial("Mean_Stress");
  double* yield = state.trial("Yield_Function");
  for (std::size_t k = 0; k < tau.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    if (fam.admitted && !fam.admitted[i]) {  // a loading-balance round holds this point elastic (Material.hpp)
      tau[k] = tauN[k] + elasticIncrement(de[k]), xi[i] = xiN[i], m[i] = druckerPragerHardening(law_, xiN[i]);
    } else {
      const DruckerPragerStep s = druckerPragerUpdate(law_, moduli().bulk, moduli().shear, tauN[k], xiN[i], de[k]);
      tau[k] = s.tau, xi[i] = s.xi, m[i] = s.m;
    }
    mean[i] = trace(tau[k]) / 3.0;  // tension positive, as the stress components
    yield[i] = druckerPragerYieldRatio(law_, tau[k], m[i]);
  }
}

}  // namespace pf
