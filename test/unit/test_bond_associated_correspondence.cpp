// Elastic Bond Associated Correspondence (materials/ElasticBondAssociatedCorrespondenceMaterial.cpp) and Elastic
// Hypoelastic Correspondence (materials/ElasticHypoelasticCorrespondenceMaterial.cpp) against closed forms on a
// generated 11x11x11 lattice (horizon 2 dx, every family built):
//  1. an affine motion y = F x with a finite, non-symmetric F gives every node's gradient F and, through the bond map
//     F_b = Fbar + (Y - Fbar xi) xi / |xi|^2, every interior bond's F_b = F;
//  2. one step from the reference (no velocities: the increment from the committed positions, dF = F - I) gives each
//     interior bond Peridigm's first-order update in closed form: L dt = (F - I) F^-1 = I - F^-1, D = sym, W = skew,
//     R = Q(W) Peridigm's rotation increment, d = R^T D R, tau = K tr(d) I + 2 mu dev(d), sigma_b = R tau R^T;
//  3. the same homogeneous state leaves an interior node (its whole family interior) without force (the bond sums
//     cancel by the family's point symmetry: a guard on the assembly, e.g. a bond weighted with the wrong end's w0,
//     J or volume, not a closed form);
//  4. (hypoelastic) the node's Velocity_Gradient and Jacobian_Determinant of that step in closed form;
//  5. Gradient Order Of Accuracy other than 1 is refused with one line naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/InputError.hpp"
#include "core/StateStore.hpp"
#include "core/Tensor3.hpp"
#include "materials/BondAssociatedKinematics.hpp"
#include "materials/CorrespondenceFields.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

using pf::operator-;
using pf::operator*;
using pf::operator+;

constexpr double kE = 200e9, kNu = 0.3;

const char* const kBondAssociated = "Elastic Bond Associated Correspondence";
const char* const kHypoelastic = "Elastic Hypoelastic Correspondence";

std::unique_ptr<pf::Material> model(const std::string& name, double order = 1.0) {
  std::map<std::string, double> v = {{"Density", 7800.0}, {"Young's Modulus", kE}, {"Poisson's Ratio", kNu},
                                     {"Gradient Order Of Accuracy", order}};
  if (name == kHypoelastic) v["Actual Horizon"] = 2e-3;
  return pf::makeMaterial(name, v, {});
}

std::unique_ptr<pf::Material> bondAssociated(double order = 1.0) { return model(kBondAssociated, order); }

// A finite, non-symmetric homogeneous gradient with det F > 0 (a stretch, shears of every sign and a turn).
const pf::Mat3 kF = {1.08, 0.13, -0.05, -0.07, 0.95, 0.11, 0.04, -0.09, 1.12};

struct AffineRun {
  pftest::Lattice L;
  pf::StateStore st;
  std::vector<double> y, f;
};

// One evaluation of the affine motion y = F x at t = 1 (start time 0, nothing committed).
void evaluateAffine(const pf::Material& mat, AffineRun& r) {
  r.L = pftest::makeLattice(11, false, 1e-3, 2.0, 0.0, pf::Influence(pf::Influence::One), false);
  r.st.allocate(mat.stateSpecs(), r.L.numQueries, r.L.fam.numBonds());
  r.y.assign(r.L.x.size(), 0.0);
  for (int p = 0; p < r.L.numNodes; ++p)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) r.y[3 * p + a] += kF[3 * a + c] * r.L.x[3 * p + c];
  r.f.assign(r.y.size(), 0.0);
  pf::FamilyView v = r.L.view();
  v.time = 1.0, v.startTime = 0.0;
  v.unitInfluence = true;  // Influence One, as the model run sets it for the deck's default
  mat.computeForce(v, r.y.data(), r.st, r.f.data());  // no exchange buffer: both phases in one call
}

// A node is interior when its distance to the lattice's faces exceeds the horizon: its family is complete.
bool interior(const pftest::Lattice& L, int p) {
  const double edge = 5.0 * L.dx;  // half-width of the 11-point lattice
  for (int a = 0; a < 3; ++a)
    if (edge - std::fabs(L.x[3 * p + a]) <= L.horizon) return false;
  return true;
}

double maxAbs(const pf::Mat3& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

TEST(BondAssociatedCorrespondence, AffineMotionGivesEveryBondTheGradient) {
  auto mat = bondAssociated();
  AffineRun r;
  evaluateAffine(*mat, r);
  pf::TensorField Fs(r.st, "Deformation_Gradient", false);
  int checked = 0;
  double worst = 0.0;
  for (int i = 0; i < r.L.numQueries; ++i) {
    const pf::Mat3 Fi{Fs.trial[0][i], Fs.trial[1][i], Fs.trial[2][i], Fs.trial[3][i], Fs.trial[4][i],
                      Fs.trial[5][i], Fs.trial[6][i], Fs.trial[7][i], Fs.trial[8][i]};
    worst = std::max(worst, maxAbs(Fi - kF));
    if (!interior(r.L, i)) continue;
    for (int b = r.L.fam.offsets[i]; b < r.L.fam.offsets[i + 1]; ++b) {
      const int j = r.L.fam.neighbors[b];
      if (!interior(r.L, j)) continue;
      const pf::Mat3 Fj{Fs.trial[0][j], Fs.trial[1][j], Fs.trial[2][j], Fs.trial[3][j], Fs.trial[4][j],
                        Fs.trial[5][j], Fs.trial[6][j], Fs.trial[7][j], Fs.trial[8][j]};
      double xi[3], Y[3];
      for (int a = 0; a < 3; ++a) xi[a] = r.L.x[3 * j + a] - r.L.x[3 * i + a], Y[a] = r.y[3 * j + a] - r.y[3 * i + a];
      worst = std::max(worst, maxAbs(pf::bondGradient(Fi, Fj, xi, Y) - kF));
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  // F = N K^-1 sums ~120 bonds of O(1) terms and inverts K: round-off of a few 1e-16 relative to |F| ~ 1.
  EXPECT_LT(worst, 1e-10 * maxAbs(kF));
}

void checkOneStepStress(const std::string& name) {
  auto mat = model(name);
  AffineRun r;
  evaluateAffine(*mat, r);
  pf::Mat3 Finv;
  pf::inverse(kF, Finv);
  const pf::Mat3 L = pf::identity3() - Finv, D = pf::sym(L), W = pf::skew(L);
  // V_n = I makes the spin correction (tr V I - V)^-1 z vanish (z_i = e_ijk D_jk = 0): Omega dt = W dt, and
  // Peridigm's increment Q = I + sin(t)/t W - (1 - cos t)/t^2 W^2, t^2 = W:W / 2 (correspondence.cxx, its sign).
  const double t = std::sqrt(0.5 * pf::ddot(W, W));
  const pf::Mat3 Q = pf::identity3() + (std::sin(t) / t) * W - ((1 - std::cos(t)) / (t * t)) * pf::mul(W, W);
  const pf::Mat3 d = pf::mulTN(Q, pf::mul(D, Q));
  const double G = kE / (2 * (1 + kNu)), K = kE / (3 * (1 - 2 * kNu));
  pf::Mat3 tau0 = (2 * G) * pf::deviator(d);
  for (int a = 0; a < 3; ++a) tau0[4 * a] += K * pf::trace(d);
  const pf::Mat3 expected = pf::mul(Q, pf::mulNT(tau0, Q));
  const double* tau[6];
  const double* R[9];
  for (int c = 0; c < 6; ++c) tau[c] = r.st.trial(std::string("Bond_Unrotated_Cauchy_Stress") + pf::kSym[c]);
  for (int c = 0; c < 9; ++c) R[c] = r.st.trial(std::string("Bond_Rotation_Tensor") + pf::kFull[c]);
  int checked = 0;
  double worst = 0.0;
  for (int i = 0; i < r.L.numQueries; ++i) {
    if (!interior(r.L, i)) continue;
    for (int b = r.L.fam.offsets[i]; b < r.L.fam.offsets[i + 1]; ++b) {
      if (!interior(r.L, r.L.fam.neighbors[b])) continue;
      double t6[6];
      for (int c = 0; c < 6; ++c) t6[c] = tau[c][b];
      const pf::Mat3 Rb{R[0][b], R[1][b], R[2][b], R[3][b], R[4][b], R[5][b], R[6][b], R[7][b], R[8][b]};
      const pf::Mat3 sigma = pf::mul(Rb, pf::mulNT(pf::fromSym6(t6), Rb));
      worst = std::max(worst, maxAbs(sigma - expected));
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  // Round-off of F_b (1e-15) through F^-1, the rotation and Hooke's law: far below 1e-10 of |sigma| ~ 2e10 Pa.
  EXPECT_LT(worst, 1e-10 * maxAbs(expected));
}

TEST(BondAssociatedCorrespondence, OneStepStressIsPeridigmsFirstOrderUpdate) { checkOneStepStress(kBondAssociated); }

// The semi-Lagrangian model reaches the same closed form: its gradient of the step's displacement u = (I - F^-1) y on
// the deformed bonds is L dt = I - F^-1 exactly, the bond map of an affine field returns it, and the update is the same.
TEST(HypoelasticCorrespondence, OneStepStressIsPeridigmsFirstOrderUpdate) { checkOneStepStress(kHypoelastic); }

void checkInteriorEquilibrium(const std::string& name) {
  auto mat = model(name);
  AffineRun r;
  evaluateAffine(*mat, r);
  // The force scale: one bond's P xi / |xi|^2 / w0 V_j summed over a family, ~ |P| / dx.
  const double scale = 4e10 / r.L.dx;
  int checked = 0;
  for (int i = 0; i < r.L.numQueries; ++i) {
    bool deep = interior(r.L, i);
    for (int b = r.L.fam.offsets[i]; deep && b < r.L.fam.offsets[i + 1]; ++b) deep = interior(r.L, r.L.fam.neighbors[b]);
    if (!deep) continue;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(r.f[3 * i + a], 0.0, 1e-12 * scale) << "node " << i << " component " << a;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(BondAssociatedCorrespondence, HomogeneousStateLeavesInteriorNodesUnloaded) { checkInteriorEquilibrium(kBondAssociated); }
TEST(HypoelasticCorrespondence, HomogeneousStateLeavesInteriorNodesUnloaded) { checkInteriorEquilibrium(kHypoelastic); }

// The node-level outputs of the semi-Lagrangian model for the same step (t = 1): Velocity_Gradient = I - F^-1 (the
// gradient of u = (I - F^-1) y over the unit step) and Jacobian_Determinant = J_N (1 + tr(L dt)) = 1 + tr(I - F^-1).
TEST(HypoelasticCorrespondence, VelocityGradientAndJacobianOfAnAffineStep) {
  auto mat = model(kHypoelastic);
  AffineRun r;
  evaluateAffine(*mat, r);
  pf::Mat3 Finv;
  pf::inverse(kF, Finv);
  const pf::Mat3 L = pf::identity3() - Finv;
  pf::TensorField Ls(r.st, "Velocity_Gradient", false);
  const double* J = r.st.trial("Jacobian_Determinant");
  double worstL = 0.0, worstJ = 0.0;
  for (int i = 0; i < r.L.numQueries; ++i) {
    for (int c = 0; c < 9; ++c) worstL = std::max(worstL, std::fabs(Ls.trial[c][i] - L[c]));
    worstJ = std::max(worstJ, std::fabs(J[i] - (1.0 + pf::trace(L))));
  }
  // M^-1 and the sums over ~33 deformed bonds: round-off of a few 1e-16 relative to |L| ~ 0.1 and J ~ 1.
  EXPECT_LT(worstL, 1e-10 * maxAbs(L));
  EXPECT_LT(worstJ, 1e-10);
}

TEST(BondAssociatedCorrespondence, HigherGradientOrderIsRefused) {
  for (const char* name : {kBondAssociated, kHypoelastic}) {
    try {
      model(name, 2.0);
      FAIL() << name << ": order 2 accepted";
    } catch (const pf::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'Gradient Order Of Accuracy'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
