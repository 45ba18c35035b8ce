#pragma once
// The shape tensor K and the approximate deformation gradient F of one node's family (Foster, Silling & Chen 2010,
// Eqs. 10 and 13; Peridigm's correspondence.cxx, computeShapeTensorInverseAndApproximateDeformationGradient): the
// kinematics of the correspondence models, and the Deformation_Gradient / Shape_Tensor_Inverse outputs the model
// computes for every material (Peridigm's compute class Deformation_Gradient). Plain arrays in, no state.
#include "core/BondFamily.hpp"
#include "core/Tensor3.hpp"

namespace pf {

// The weight of bond b in every family sum: omega V_j (times the partial-volume fraction); 0 for a bond flagged in
// fam.brokenN (omega' = 0, Li & Geng Eq. 49).
inline double bondWeight(const FamilyView& fam, int b) {
  if (fam.brokenN && fam.brokenN[b] != 0.0) return 0.0;
  const double w = fam.unitInfluence ? 1.0 : fam.influence[b];
  const double v = fam.volume[fam.neighbors[b]];
  return fam.fraction ? w * v * fam.fraction[b] : w * v;
}

// K = sum w xi (x) xi and N = sum w Y (x) xi of owned node i (Y: the deformed bond at positions y), with the number
// of bonds that count and K's quality det K / (tr K / d)^d: 1 for an isotropic family, 0 for a degenerate one.
struct FamilySums {
  Mat3 K{}, N{};
  int bonds = 0;
  double quality = 0.0;
};
FamilySums familySums(const FamilyView& fam, int i, const double* y, bool planar);

struct ShapeAndGradient {
  Mat3 Kinv;  // K^-1 (planar: the in-plane 2x2 inverse, zz = 0)
  Mat3 F;     // deformation gradient N K^-1 (planar: F_zz = 1, no out-of-plane shear)
};

// K^-1 and F of owned node i; false when K is singular or ill-conditioned (fewer than three non-coplanar bonds, two
// non-parallel ones in 2D; out is then unset). planar: the family lies in z = 0.
bool tryShapeAndGradient(const FamilyView& fam, int i, const double* y, bool planar, ShapeAndGradient& out);

}  // namespace pf
