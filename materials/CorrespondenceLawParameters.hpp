#pragma once
// The parameters of the plastic laws the correspondence models share, standard and bond-associated (declared once,
// read once): Peridigm's J2 returns (Yield Stress, Hardening Modulus), Foster et al.'s viscoplastic law and Li &
// Geng's Drucker-Prager law.
#include <vector>

#include "DruckerPragerPlasticity.hpp"
#include "FosterViscoplasticity.hpp"
#include "core/Parameters.hpp"

namespace pf {

struct ParameterValues;
using MaterialInput = ParameterValues;

// "Yield Stress" and, with hardening, "Hardening Modulus".
std::vector<ParameterSpec> peridigmJ2Parameters(bool hardening);
// Foster et al. (2010) Eqs. 58-59: "Yield Stress", "Strain Hardening Exponent", "Rate Sensitivity Exponent",
// "Reference Plastic Strain", "Reference Plastic Strain Rate".
std::vector<ParameterSpec> fosterParameters();
FosterLaw fosterLawFrom(const MaterialInput& in);
// Li & Geng Eq. 38, A14: "Friction Angle", "Cohesion", "Initial Hardening Parameter", "Hardening Rate",
// "Dilatancy Ratio".
std::vector<ParameterSpec> druckerPragerParameters();
DruckerPragerLaw druckerPragerLawFrom(const MaterialInput& in);

}  // namespace pf
