#include "CorrespondenceLawParameters.hpp"

#include "core/MaterialEntry.hpp"

namespace pf {

std::vector<ParameterSpec> peridigmJ2Parameters(bool hardening) {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = {P::real("Yield Stress", "Y, the initial yield stress [Pa]").need().positive()};
  if (hardening) params.push_back(P::real("Hardening Modulus", "H [Pa]: the yield stress is Y + H eps_p").need());
  return params;
}

std::vector<ParameterSpec> fosterParameters() {
  using P = ParameterSpec;
  return {P::real("Yield Stress", "Y, quasi-static yield stress [Pa] (Foster et al. 2010 Eq. 59)").need().positive(),
          P::real("Strain Hardening Exponent", "n of Eq. 59").need().positive(),
          P::real("Rate Sensitivity Exponent", "m of Eq. 58").need().positive(),
          P::real("Reference Plastic Strain", "eps_0 of Eq. 59 (dimensionless)").need().positive(),
          P::real("Reference Plastic Strain Rate", "rate_0 of Eq. 58 [1/s]").need().positive()};
}

FosterLaw fosterLawFrom(const MaterialInput& in) {
  return FosterLaw{in.get("Yield Stress"), in.get("Strain Hardening Exponent"), in.get("Rate Sensitivity Exponent"),
                   in.get("Reference Plastic Strain"), in.get("Reference Plastic Strain Rate")};
}

std::vector<ParameterSpec> druckerPragerParameters() {
  using P = ParameterSpec;
  return {P::real("Friction Angle", "internal friction angle phi [degrees] of A, B (Li & Geng Eq. 38)")
              .need().nonNegative().below(90.0),
          P::real("Cohesion", "c of B (Eq. 38) [Pa]").need().nonNegative(),
          P::real("Initial Hardening Parameter", "m0 of Eq. A14: initial yield at J = m0 (A I + B)")
              .need().positive().atMost(1.0),
          P::real("Hardening Rate", "h of Eq. A14 (0: perfectly plastic)").need().nonNegative(),
          // [0, 1], not (0, 1]: the paper's Table 2 tests 1-6 use d0 = 0 (plastic flow without volume change).
          P::real("Dilatancy Ratio", "d0 of the potential g (Eq. 38); 1: associated flow, 0: no dilatancy")
              .need().nonNegative().atMost(1.0)};
}

DruckerPragerLaw druckerPragerLawFrom(const MaterialInput& in) {
  return druckerPragerLaw(in.get("Friction Angle"), in.get("Cohesion"), in.get("Initial Hardening Parameter"),
                          in.get("Hardening Rate"), in.get("Dilatancy Ratio"));
}

}  // namespace pf
