#pragma once
// Peridigm's shear correction factor of the OSB deviatoric term (Peridigm material_utilities.cxx,
// computeShearCorrectionFactor, inverted as Peridigm_ElasticPlasticHardeningMaterial.cpp::initialize does):
// a per-node scalar s_i from the reference family alone, so that s_i times the family's deviatoric energy
// under pure shear equals the continuum sphere's. No allocation, no state; 3D families.
#include "core/BondFamily.hpp"

namespace pf {

// For owned nodes i in [fam.begin, fam.end): s_i = 15 max_mode D_mode / (4 gamma^2 m_i), where D_mode =
// sum_j omega (e^d_ij)^2 V_j under the pure shear y = x + gamma (xi_b, xi_a) in the plane of the mode (xy,
// zx, yz; gamma = 1e-6, node i fixed), e^d = e - theta |xi| / 3, theta = 3 sum omega |xi| e V / m. The
// continuum sphere has D = 4 gamma^2 m / 15, i.e. s = 1. V_j carries the bond's partial-volume share.
void osbShearCorrectionFactor(const FamilyView& fam, double* scf);

}  // namespace pf
