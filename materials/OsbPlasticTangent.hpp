#pragma once
// The consistent (algorithmic) tangent of the OSB J2 solid (osbJ2Force): the exact directional derivative of
// its force, return mapping included, at deformed positions y with the committed state n held fixed. What
// Newton's method needs for quadratic convergence within a load step (Simo & Hughes 1998 §3.3, applied to
// Pirzadeh et al. 2024 §3.2); the derivation is in docs/materials.md, "Consistent tangent".
#include <cstddef>
#include <vector>

#include "core/BondFamily.hpp"
#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"
#include "OsbPlasticKernels.hpp"

namespace pf {

// Adds to dforce (3 per overlap node) the derivative of osbJ2Force(fam, p, y, s, .) along dy (3 per overlap
// node), with the same two-ended accumulation. Reads only the committed fields of s (edpN, lambdaN, alphaN,
// qN, signN) and s.scf; writes no state but the bond-damage trial flags the force's gather writes. Returns
// false where the return mapping fails at y (the force itself throws there).
bool osbJ2ForceDerivative(const FamilyView& fam, const J2Parameters& p, const double* y, const double* dy,
                          const J2Fields& s, double* dforce);

// The part of the derivative at y that does not depend on the direction, kept so that the Krylov products at one
// Newton point skip the return mapping (issue 35's cached linearisation): per owned node of the view (from
// fam.begin) its return and the dilatation of its force at y; the position records of every overlap node. Bond
// quantities are recomputed per product from the positions (the force kernel's gather and trial pass): keeping them
// took 56 bytes per bond and left each product waiting on memory (docs/benchmark-log.md, "Cached linearisation").
struct J2NodeTangent {
  OsbJ2Return r{};
  double theta = 0.0;
};
struct J2Tangent {
  std::vector<J2NodeTangent> node;
  std::vector<double> records;    // the buffer behind pos
  const osb::Quad* pos = nullptr;  // (y_j, V_j) per overlap node
  // `Gradient Correction` = `Quadratic` only, per owned node (OsbGradientCorrection.hpp): whether its fit at y is
  // regular, the quadratic rows of its M^-1 (osb::kMaxFitRows) and the quadratic coefficients of its Y
  // (osb::kMaxFitCoefficients), so that a product applies the fit without forming M or fitting Y again.
  std::vector<unsigned char> fitKept;
  std::vector<double> fitRows, fitQ;
  std::size_t bytes() const;
};

// Fills tan at y, writing the bond-damage trial flags the force's gather writes; false where the return mapping
// fails at y.
bool osbJ2Linearise(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s, J2Tangent& tan);
// Adds to dforce the derivative along dy at the y of tan: the same bits as osbJ2ForceDerivative at that y. Reads the
// committed fields of s, as osbJ2Linearise did.
void osbJ2TangentProduct(const FamilyView& fam, const J2Parameters& p, const J2Fields& s, const J2Tangent& tan,
                         const double* dy, double* dforce);

}  // namespace pf
