#pragma once
// The kinematics every correspondence (non-ordinary state-based) model shares, per owned node of a family:
// shape tensor K and deformation gradient F (Foster et al. 2010 Eqs. 10, 13), the Flanagan-Taylor rotation
// update with the unrotated strain increment (Eqs. 14-18), first Piola stress (Eqs. 23-24), the force state
// T<xi> = omega P K^-1 xi (Eq. 25) and Peridigm's hourglass force. Plain arrays in, no state.
#include "core/BondFamily.hpp"
#include "core/ShapeTensor.hpp"
#include "core/Tensor3.hpp"

namespace pf {

// K = sum omega xi (x) xi V_j and F = (sum omega Y (x) xi V_j) K^-1 of owned node i (V_j times the bond's
// partial-volume fraction; a bond flagged in fam.brokenN takes omega' = 0, Li & Geng Eq. 49). planar: the family lies in z = 0. Throws InputError naming the point when K is
// singular or ill-conditioned (fewer than three non-coplanar bonds, two non-parallel ones in 2D).
ShapeAndGradient shapeAndGradient(const FamilyView& fam, int i, const double* y, bool planar);
// The same without the throw: core/ShapeTensor.hpp's tryShapeAndGradient.

// One step of the Flanagan & Taylor (1987) polar update from F_n to F: the increment L dt = (F - F_n) F_mid^-1
// (F_mid = (F_n + F)/2), D dt = sym, W dt = skew; the spin of the rotation Omega = W + (tr V I - V)^-1 z
// (T&F Eqs. 10-13) with V at the half step (predicted from V_n), integrated by the Cayley map
// R = (I - Omega/2)^-1 (I + Omega/2) R_n (T&F Eq. 39): second order in dt; the left stretch V = sym(F R^T). Returns the unrotated strain increment d dt = R_h^T (D dt) R_h with R_h the
// rotation at the half step (D dt is a midpoint quantity). Throws ConstitutiveFailure if F_mid is singular.
struct PolarUpdate {
  Mat3 R, V;   // at the end of the step
  Mat3 dUnrot; // d dt (Foster Eq. 18 times dt)
};
// Throws ConstitutiveFailure when det F <= 0 at owned node i, naming the point, its displacement and its
// bonds' state (how many turned around, the range of stretches) and the usual causes.
void requirePositiveJacobian(const FamilyView& fam, int i, const double* y, const Mat3& F);

PolarUpdate flanaganTaylor(const Mat3& Fn, const Mat3& F, const Mat3& Rn, const Mat3& Vn);
// Peridigm's update (correspondence.cxx, computeUnrotatedRateOfDeformationAndRotationTensor), first order, on the
// end-of-step rate: L dt = (Fdot dt) F^-1 with F the end of the step and Fdot dt the step's gradient increment,
// Peridigm's velocity-state gradient times dt (velocityGradient) or F - F_n without velocities (its QuasiStatic
// velocity is the step's displacement increment over dt); the spin from V_n; R = Q R_n with Peridigm's Q (see the
// .cpp); V = V_n + L V_n - V_n Omega (dt-scaled); d dt = R^T D R.
PolarUpdate peridigmPolarUpdate(const Mat3& dFdt, const Mat3& F, const Mat3& Rn, const Mat3& Vn);

// Peridigm's velocity-state gradient of owned node i, Fdot = (sum omega (v_j - v_i) (x) xi V_j) K^-1 (correspondence.cxx,
// computeUnrotatedRateOfDeformationAndRotationTensor), with the weights of shapeAndGradient; v: 3 per overlap node.
// planar: no out-of-plane rate (F_zz stays 1).
Mat3 velocityGradient(const FamilyView& fam, int i, const double* v, const Mat3& Kinv, bool planar);

// First Piola-Kirchhoff stress P = det(F) sigma F^-T with sigma = R tau R^T (Foster Eqs. 23-24).
Mat3 piolaFromUnrotated(const Mat3& F, const Mat3& R, const Mat3& tau);

// Adds the force state T<xi> = omega A xi with A = P K^-1 of owned node i: f_i += T V_j, f_j -= T V_i.
void addCorrespondenceForce(const FamilyView& fam, int i, const Mat3& A, double* force);

// The same two forces in gather form: owned node i's whole force density from its own family, each bond
// counted from both ends, f_i += [omega (A_i + A_j) xi + hourglass of both ends] V_j (a neighbour's reaction
// with the bond's own omega and partial-volume fraction: equal at both ends for equal horizons). rows: per
// overlap node, stride values A (9), F (9), c (1), 1, sigma1 (kGatherRow; a row of zeros marks a node of a
// one-pass model, which adds its own reactions to i and receives i's as f_j -= T_i V_i). The sums run in
// the family's order whatever the partition. sigma1 (kRowS1): the largest principal Cauchy stress, for the
// Maximum Principal Stress damage model (core/StressDamage.hpp; +inf for a point whose intact bonds no longer
// give a regular K, so that its remaining bonds break).
constexpr int kRowA = 0, kRowF = 9, kRowC = 18, kRowFlag = 19, kRowS1 = 20, kGatherRow = 21;
// With the NDO band the row also holds P (9 values, row-major) at kRowP and the node's own K^-1 at kRowKinv (K is
// constant without damage: completeForce reads it instead of rebuilding it from the family on every evaluation).
constexpr int kRowP = 21, kRowKinv = 30, kBandRow = 39;
// broken: per bond, the trial flags (1: the bond is absent from both ends' sums, stress and hourglass), or null.
// hourglass: where to write the hourglass part of f_i (3 values; Peridigm's Hourglass_Force_Density), or null.
void addGatheredForce(const FamilyView& fam, int i, const double* y, const double* rows, int stride, double* force,
                      const double* broken = nullptr, double* hourglass = nullptr);

// Li & Geng (seed 003) Eqs. 31-32 for owned node i of the surface band (fam.band): the NDO divergence
// f_i += sum omega (P_j - P_i) K_i^-1 xi V_j, the hourglass term of addGatheredForce, and the traction term
// -P_i n_i / dx of the outer layer (fam.outerNormal, fam.layerThickness). rows: kBandRow values per node.
void addBandForce(const FamilyView& fam, int i, const double* y, const Mat3& Kinv, const double* rows, int stride,
                  double* force, const double* broken = nullptr, double* hourglass = nullptr);

// Peridigm's hourglass (zero-energy mode) force of owned node i: per bond, with the deformed bond Y and
// its affine image F xi, T = c ((Y - F xi) . Y/|Y|) / |xi| Y/|Y|, added as f_i += T V_j, f_j -= T V_i.
// c = Hourglass Coefficient times the micromodulus of the bond-based solid with the model's bulk
// modulus (CorrespondenceMaterial). Zero for every affine motion.
void addHourglassForce(const FamilyView& fam, int i, const double* y, const Mat3& F, double c, double* force);

// The work the hourglass forces of owned node i's bonds take from the body over a step from the deformed
// positions yN (gradient FN) to y (gradient F), by the trapezoid rule: sum (T_n + T) . (Y - Y_n) V_i V_j.
// The force has no potential (F moves with the family, Y/|Y| turns), so its energy is this accumulated work,
// not a spring energy of the current state (docs/materials.md, "Energy").
double hourglassWork(const FamilyView& fam, int i, const double* yN, const Mat3& FN, const double* y, const Mat3& F,
                     double c);

}  // namespace pf
