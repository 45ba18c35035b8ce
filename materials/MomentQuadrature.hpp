#pragma once
// Quadrature weights for the bond sum of heat conduction, sum_j c (T_j - T_i) / |xi| w_j, that make it exact, at every
// point and whatever the family's shape, for the temperature fields up to second order: for each point i the weights
// w_j closest to the volumes V_j (least squares weighted by 1/V_j) with
//   sum_j w_j xi_a / |xi| = 0,   sum_j w_j xi_a xi_b / |xi| = delta_ab pi delta^4 / 3   (a, b = x, y, z),
// the moments of the whole ball. The role of Peridigm's "Use Improved Quadrature" (its weights come from a library
// outside its repository, so they are not reproduced; a linear field then conducts no heat at any point, the
// property its DiffusionImprovedQuadrature deck tests). A family that does not span three directions keeps V_j.
#include <vector>

#include "core/BondFamily.hpp"

namespace pf {

// The weights of the bonds of owned nodes [fam.begin, fam.end), indexed as fam.neighbors from fam.offsets[fam.begin].
std::vector<double> momentQuadratureWeights(const FamilyView& fam);

}  // namespace pf
