#pragma once
// Thermal expansion in the linear OSB solid ("Elastic" with Thermal Expansion Coefficient): every bond of node i
// less its free thermal extension e_th = a dT_i |xi| in the dilatation, the deviatoric extension and the critical
// stretch (Peridigm's elastic model: node i's Temperature_Change, its own family's bonds). a is alpha in 3D and
// plane stress, (1 + nu) alpha in plane strain (the out-of-plane constraint adds nu alpha dT to the free in-plane
// strain), so a free body expands force-free and a clamped one carries -3 kappa alpha dT (3D). A scalar loop
// beside the vectorised mechanics-only kernels, which stay untouched.
#include "OsbConstants.hpp"
#include "core/BondFamily.hpp"

namespace pf {

// theta (per owned node) and the force of the bonds of [fam.begin, fam.end), as osbElasticDilatationAndForce.
// dT: per overlap node; a: the thermal coefficient above.
void osbThermoelasticDilatationAndForce(const FamilyView& fam, const OsbConstants& c, double a, const double* dT,
                                        const double* y, double* theta, double* force);

}  // namespace pf
