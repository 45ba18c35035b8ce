#pragma once
// The consistent (algorithmic) tangent of the OSB J2 solid (osbJ2Force): the exact directional derivative of
// its force, return mapping included, at deformed positions y with the committed state n held fixed. What
// Newton's method needs for quadratic convergence within a load step (Simo & Hughes 1998 §3.3, applied to
// Pirzadeh et al. 2024 §3.2); the derivation is in docs/materials.md, "Consistent tangent".
#include "core/BondFamily.hpp"
#include "OsbPlasticKernels.hpp"

namespace pf {

// Adds to dforce (3 per overlap node) the derivative of osbJ2Force(fam, p, y, s, .) along dy (3 per overlap
// node), with the same two-ended accumulation. Reads only the committed fields of s (edpN, lambdaN, alphaN,
// qN, signN) and s.scf; writes no state but the bond-damage trial flags the force's gather writes. Returns
// false where the return mapping fails at y (the force itself throws there).
bool osbJ2ForceDerivative(const FamilyView& fam, const J2Parameters& p, const double* y, const double* dy,
                          const J2Fields& s, double* dforce);

}  // namespace pf
