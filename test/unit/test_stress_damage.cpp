// Damage by stress (core/StressDamage.hpp; Li & Geng, seed 003, Eqs. 49-51). References independent of the
// code under test: the largest principal stress against eigenvalues known by construction (Q diag Q^T with an
// explicit rotation Q) and the 2D Mohr-circle formula; the bond rule against Eq. 50 written out; and the gather
// form of Elastic Correspondence with damage on a whole lattice against the closed form sigma1 = E eps of an
// affine uniaxial stress (every bond breaks when E eps > f_t, none when below), with the two half-bonds of each
// bond agreeing under a non-affine motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/StressDamage.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/CorrespondenceKinematics.hpp"

namespace {

// s = Q diag(l) Q^T in (xx, yy, zz, xy, yz, xz) order, Q a rotation by angle a about the unit axis n.
void rotated(const double l[3], const double n[3], double a, double* s) {
  const double c = std::cos(a), sn = std::sin(a), t = 1.0 - c;
  const double Q[3][3] = {{c + n[0] * n[0] * t, n[0] * n[1] * t - n[2] * sn, n[0] * n[2] * t + n[1] * sn},
                          {n[1] * n[0] * t + n[2] * sn, c + n[1] * n[1] * t, n[1] * n[2] * t - n[0] * sn},
                          {n[2] * n[0] * t - n[1] * sn, n[2] * n[1] * t + n[0] * sn, c + n[2] * n[2] * t}};
  double S[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S[i][j] = 0.0;
      for (int k = 0; k < 3; ++k) S[i][j] += Q[i][k] * l[k] * Q[j][k];
    }
  s[0] = S[0][0], s[1] = S[1][1], s[2] = S[2][2], s[3] = S[0][1], s[4] = S[1][2], s[5] = S[0][2];
}

TEST(StressDamage, MaxPrincipalOfRotatedDiagonalTensors) {
  const double n[3] = {1.0 / std::sqrt(14.0), 2.0 / std::sqrt(14.0), 3.0 / std::sqrt(14.0)};
  // Well separated eigenvalues: round-off of the cubic's closed form, 1e-12 of the largest |eigenvalue|.
  const double cases[][3] = {{3e6, 1e6, -2e6}, {-1e6, -2e6, -5e6}, {1e6, 7e6, 2e6}, {0.5, -0.25, 0.1}};
  for (const auto& l : cases)
    for (double a : {0.0, 0.3, 1.1, 2.7}) {
      double s[6];
      rotated(l, n, a, s);
      const double ref = std::max({l[0], l[1], l[2]});
      const double scale = std::max({std::fabs(l[0]), std::fabs(l[1]), std::fabs(l[2])});
      EXPECT_NEAR(pf::maxPrincipal(s), ref, 1e-12 * scale) << l[0] << " " << l[1] << " " << l[2] << " a=" << a;
    }
  // Two largest equal (q = -1 in the closed form, where acos loses half the digits): sqrt(eps) ~ 1e-8 relative,
  // bound 1e-7. Two smallest equal (q = +1) and all three equal are exact to round-off.
  const double degenerate[][3] = {{2e6, 2e6, -1e6}, {2e6, -1e6, -1e6}, {4e5, 4e5, 4e5}};
  for (const auto& l : degenerate) {
    double s[6];
    rotated(l, n, 0.7, s);
    EXPECT_NEAR(pf::maxPrincipal(s), std::max({l[0], l[1], l[2]}), 1e-7 * 2e6);
  }
}

TEST(StressDamage, MaxPrincipalMatchesMohrCircleInPlane) {
  // sigma1 = (sx + sy)/2 + sqrt(((sx - sy)/2)^2 + txy^2) when it exceeds szz (plane stress: szz = 0).
  const double cases[][3] = {{1e6, -3e5, 4e5}, {-2e6, -1e6, 3e5}, {5e5, 5e5, 1e5}, {0.0, 0.0, 1e6}};
  for (const auto& c : cases) {
    const double s[6] = {c[0], c[1], 0.0, c[2], 0.0, 0.0};
    const double mohr = 0.5 * (c[0] + c[1]) + std::sqrt(0.25 * (c[0] - c[1]) * (c[0] - c[1]) + c[2] * c[2]);
    EXPECT_NEAR(pf::maxPrincipal(s), std::max(mohr, 0.0), 1e-12 * 3e6);
  }
}

TEST(StressDamage, BondRuleIsEq50AndNeverHeals) {
  const double ft = 1e6;
  EXPECT_FALSE(pf::bondBrokenByStress(0.0, 0.9e6, 1.1e6, ft));  // mean exactly f_t: not above it
  EXPECT_TRUE(pf::bondBrokenByStress(0.0, 0.9e6, 1.2e6, ft));   // mean 1.05e6
  EXPECT_FALSE(pf::bondBrokenByStress(0.0, 2.5e6, -0.6e6, ft)); // one end far above, mean 0.95e6
  EXPECT_TRUE(pf::bondBrokenByStress(1.0, -5e6, -5e6, ft));     // broken before: stays broken under compression
  EXPECT_TRUE(pf::bondBrokenByStress(0.0, HUGE_VAL, 0.0, ft));  // a detached end (sigma1 = +inf)
  EXPECT_FALSE(pf::bondBrokenByStress(0.0, 5e6, 5e6, HUGE_VAL));  // frozen rounds: nothing new breaks
}

// Elastic Correspondence on a whole 3D lattice in gather form with Maximum Principal Stress damage.
struct DamagedRun {
  std::vector<double> broken, damage, force, rows;
};

DamagedRun evaluate(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y, double ft,
                    const std::vector<double>& brokenN) {
  DamagedRun r;
  const std::size_t nb = L.fam.numBonds();
  r.broken.assign(nb, 0.0);
  r.damage.assign(L.numNodes, 0.0);
  r.force.assign(L.x.size(), 0.0);
  std::vector<double> count(L.numNodes, 0.0), countN(L.numNodes, 0.0);
  std::vector<double> rows(static_cast<std::size_t>(pf::kGatherRow) * L.numNodes, 0.0);
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, nb);
  pf::FamilyView v = L.view();
  v.exchange = rows.data(), v.exchangeStride = pf::kGatherRow;
  v.brokenN = brokenN.data(), v.broken = r.broken.data(), v.damage = r.damage.data();
  v.brokenCountN = countN.data(), v.brokenCount = count.data();
  v.tensileStrength = ft;
  mat.computeForce(v, y.data(), st, r.force.data());
  mat.completeForce(v, y.data(), st, r.force.data());
  r.rows = rows;
  return r;
}

TEST(StressDamage, UniaxialAffineStressBreaksEveryBondExactlyAboveTensileStrength) {
  const double E = 27e9, nu = 0.18, eps = 5e-5;  // sigma1 = E eps = 1.35 MPa (small strain: O(eps) relative)
  auto mat = pf::makeMaterial("Elastic Correspondence", {{"Density", 2400.0}, {"Young's Modulus", E},
                                                          {"Poisson's Ratio", nu}, {"Hourglass Coefficient", 0.0}});
  const pftest::Lattice L = pftest::makeLattice(7, false, 1e-3, 3.0, 1e-3, pf::Influence(pf::Influence::One), false);
  ASSERT_EQ(L.numQueries, L.numNodes);
  std::vector<double> y(L.x);
  for (int p = 0; p < L.numNodes; ++p)
    y[3 * p] += eps * L.x[3 * p], y[3 * p + 1] -= nu * eps * L.x[3 * p + 1], y[3 * p + 2] -= nu * eps * L.x[3 * p + 2];
  const std::vector<double> none(L.fam.numBonds(), 0.0);
  // The affine field gives every point (surface ones too) F exact and sigma1 = E eps to O(eps) (the rate form's
  // finite-strain terms): 1 % either side of E eps decides every bond.
  const DamagedRun below = evaluate(*mat, L, y, 1.01 * E * eps, none);
  const DamagedRun above = evaluate(*mat, L, y, 0.99 * E * eps, none);
  EXPECT_EQ(*std::max_element(below.broken.begin(), below.broken.end()), 0.0);
  EXPECT_EQ(*std::min_element(above.broken.begin(), above.broken.end()), 1.0);
  for (int p = 0; p < L.numNodes; ++p) EXPECT_EQ(above.damage[p], 1.0);
  // Broken bonds carry no force: with every bond broken the body is force free.
  for (double f : above.force) EXPECT_EQ(f, 0.0);
}

TEST(StressDamage, HalfBondsAgreeAndBrokenBondsLeaveTheForce) {
  auto mat = pf::makeMaterial("Elastic Correspondence", {{"Density", 2400.0}, {"Young's Modulus", 27e9},
                                                          {"Poisson's Ratio", 0.18}, {"Hourglass Coefficient", 0.1}});
  const pftest::Lattice L = pftest::makeLattice(7, false, 1e-3, 3.0, 1e-3, pf::Influence(pf::Influence::One), false);
  std::vector<double> y(L.x);
  for (int p = 0; p < L.numNodes; ++p) {
    const double* x = &L.x[3 * p];
    y[3 * p] += 1e-4 * x[0] + 0.05 * x[1] * x[1];
    y[3 * p + 1] += 2e-5 * x[1] + 0.03 * x[0] * x[2];
    y[3 * p + 2] += -1e-5 * x[2];
  }
  const std::vector<double> none(L.fam.numBonds(), 0.0);
  // f_t at the median sigma1 of the undamaged evaluation's bonds: some but not all break.
  const DamagedRun probe = evaluate(*mat, L, y, HUGE_VAL, none);
  EXPECT_EQ(*std::max_element(probe.broken.begin(), probe.broken.end()), 0.0);
  std::vector<double> rows(static_cast<std::size_t>(pf::kGatherRow) * L.numNodes, 0.0);
  {
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    pf::FamilyView v = L.view();
    std::vector<double> f(L.x.size(), 0.0), b(L.fam.numBonds()), d(L.numNodes), c(L.numNodes);
    v.exchange = rows.data(), v.exchangeStride = pf::kGatherRow;
    v.brokenN = none.data(), v.broken = b.data(), v.damage = d.data(), v.brokenCountN = c.data(), v.brokenCount = c.data();
    v.tensileStrength = HUGE_VAL;
    mat->computeForce(v, y.data(), st, f.data());
  }
  std::vector<double> s1(L.numNodes);
  for (int p = 0; p < L.numNodes; ++p) s1[p] = rows[static_cast<std::size_t>(pf::kGatherRow) * p + pf::kRowS1];
  std::vector<double> sorted(s1);
  std::sort(sorted.begin(), sorted.end());
  ASSERT_LT(sorted.front(), sorted.back());
  const double ft = sorted[sorted.size() / 2];
  const DamagedRun r = evaluate(*mat, L, y, ft, none);
  int nBroken = 0;
  for (int i = 0; i < L.numNodes; ++i)
    for (int b = L.fam.offsets[i]; b < L.fam.offsets[i + 1]; ++b) {
      const int j = L.fam.neighbors[b];
      EXPECT_EQ(r.broken[b], 0.5 * (s1[i] + s1[j]) > ft ? 1.0 : 0.0);  // Eq. 50 from the rows' sigma1
      int back = -1;  // the half-bond (j, i)
      for (int c = L.fam.offsets[j]; c < L.fam.offsets[j + 1]; ++c)
        if (L.fam.neighbors[c] == i) back = c;
      ASSERT_GE(back, 0);
      EXPECT_EQ(r.broken[b], r.broken[back]);
      nBroken += r.broken[b] != 0.0;
    }
  EXPECT_GT(nBroken, 0);
  EXPECT_LT(nBroken, static_cast<int>(L.fam.numBonds()));
  // Damage = broken / total (Eq. 51).
  for (int i = 0; i < L.numNodes; ++i) {
    double k = 0;
    for (int b = L.fam.offsets[i]; b < L.fam.offsets[i + 1]; ++b) k += r.broken[b];
    EXPECT_EQ(r.damage[i], k / (L.fam.offsets[i + 1] - L.fam.offsets[i]));
  }
  // The force leaves the trial broken bonds out: it differs from the undamaged one (same K, F: brokenN is none).
  double diff = 0.0;
  for (std::size_t k = 0; k < r.force.size(); ++k) diff = std::max(diff, std::fabs(r.force[k] - probe.force[k]));
  EXPECT_GT(diff, 0.0);
  // With these breaks as the committed set, K and F leave them out too (omega' = 0, Eq. 49): a different force again.
  const DamagedRun next = evaluate(*mat, L, y, HUGE_VAL, r.broken);
  EXPECT_EQ(next.broken, r.broken);  // frozen: exactly the base set
  double diff2 = 0.0;
  for (std::size_t k = 0; k < r.force.size(); ++k) diff2 = std::max(diff2, std::fabs(r.force[k] - next.force[k]));
  EXPECT_GT(diff2, 0.0);
}

// A point whose intact bonds leave K singular is detached: no stress and no force from it, sigma1 = +inf in its row
// so that its remaining bonds break at the next decision (and only then: frozen rounds keep the base set).
TEST(StressDamage, PointWithoutRegularShapeTensorIsDetached) {
  auto mat = pf::makeMaterial("Elastic Correspondence", {{"Density", 2400.0}, {"Young's Modulus", 27e9},
                                                          {"Poisson's Ratio", 0.18}, {"Hourglass Coefficient", 0.1}});
  const pftest::Lattice L = pftest::makeLattice(5, false, 1e-3, 3.0, 1e-3, pf::Influence(pf::Influence::One), false);
  std::vector<double> y(L.x);
  for (int p = 0; p < L.numNodes; ++p) y[3 * p] += 1e-4 * L.x[3 * p] + 0.02 * L.x[3 * p + 1] * L.x[3 * p + 1];
  // Node 0 keeps only its bonds along x (collinear: K singular); every other bond stays intact.
  std::vector<double> brokenN(L.fam.numBonds(), 0.0);
  const int i0 = 0;
  for (int b = L.fam.offsets[i0]; b < L.fam.offsets[i0 + 1]; ++b) {
    const int j = L.fam.neighbors[b];
    const bool alongX = L.x[3 * j + 1] == L.x[1] && L.x[3 * j + 2] == L.x[2];
    if (alongX) continue;
    brokenN[b] = 1.0;
    for (int c = L.fam.offsets[j]; c < L.fam.offsets[j + 1]; ++c)
      if (L.fam.neighbors[c] == i0) brokenN[c] = 1.0;  // its other half
  }
  const DamagedRun frozen = evaluate(*mat, L, y, HUGE_VAL, brokenN);
  EXPECT_EQ(frozen.broken, brokenN);  // nothing new while frozen
  const DamagedRun open = evaluate(*mat, L, y, 1e30, brokenN);  // f_t far above any finite sigma1
  int along = 0;
  for (int b = L.fam.offsets[i0]; b < L.fam.offsets[i0 + 1]; ++b) {
    EXPECT_EQ(open.broken[b], 1.0);  // sigma1_0 = +inf breaks its remaining bonds
    along += brokenN[b] == 0.0;
  }
  ASSERT_GT(along, 0);
  EXPECT_EQ(open.damage[i0], 1.0);
  // Its row: no stress (A = P K^-1 = 0), no hourglass constant, sigma1 = +inf; its neighbours' rows are regular.
  const double* row = &frozen.rows[0];
  for (int k = 0; k < 9; ++k) EXPECT_EQ(row[pf::kRowA + k], 0.0);
  EXPECT_EQ(row[pf::kRowC], 0.0);
  EXPECT_EQ(row[pf::kRowS1], HUGE_VAL);
  EXPECT_TRUE(std::isfinite(frozen.rows[static_cast<std::size_t>(pf::kGatherRow) * L.fam.neighbors[L.fam.offsets[i0]] +
                                       pf::kRowS1]));
}

}  // namespace
