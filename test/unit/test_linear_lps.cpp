// Unit tests of "Linear LPS Partial Volume" (materials/LinearLpsMaterial: Peridigm's linearised LPS solid) against
// closed forms and against the nonlinear "Elastic" solid it linearises:
//  1. an affine displacement u = eps x gives the centre of a cubic lattice theta = tr(eps) (the lattice's second
//     moment is m/3 I by symmetry) and zero force;
//  2. for a small random motion its force is Elastic's to first order (the difference is quadratic in the motion);
//  3. its tangent is the force of du itself, exactly (a linear model), so Newton converges in one step.
// Units: SI; E = 200 GPa, nu = 0.3, dx = 1 mm, horizon 3.015 dx.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "LatticeFixture.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

constexpr double kE = 200e9, kNu = 0.3, kDx = 1e-3;

std::unique_ptr<pf::Material> linearLps() {
  return pf::makeMaterial("Linear LPS Partial Volume",
                          {{"Density", 7800.0}, {"Young's Modulus", kE}, {"Poisson's Ratio", kNu}});
}

std::vector<double> forceOf(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y,
                            double* thetaCentre = nullptr) {
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  std::vector<double> F(3 * L.numNodes, 0.0);
  mat.computeForce(L.view(), y.data(), st, F.data());
  if (thetaCentre) *thetaCentre = st.trial("Dilatation")[0];
  return F;
}

double maxAbs(const std::vector<double>& v) {
  double a = 0.0;
  for (double x : v) a = std::max(a, std::fabs(x));
  return a;
}

}  // namespace

// 1. Exact up to round-off: theta sums ~120 bond terms of size |eps| (1e-15 relative each, 1e-13 allowed); the
// centre's force is a sum of terms of size E |eps| / dx that cancel pairwise (1e-12 of that scale allowed).
TEST(LinearLps, AffineMotionGivesTraceAndNoInteriorForce) {
  const auto L = pftest::makeLattice(9, false, kDx, 3.015, 0.0, pf::Influence::One, /*centreOnly=*/true);
  const double eps[3][3] = {{1e-3, 2e-4, -3e-4}, {5e-4, -2e-3, 1e-4}, {-1e-4, 7e-4, 4e-4}};
  std::vector<double> y = L.x;
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) y[3 * p + a] += eps[a][b] * L.x[3 * p + b];
  auto mat = linearLps();
  double theta = 0.0;
  const auto F = forceOf(*mat, L, y, &theta);
  EXPECT_NEAR(theta, eps[0][0] + eps[1][1] + eps[2][2], 1e-13);
  const double scale = kE * 2e-3 / kDx;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(F[c], 0.0, 1e-12 * scale) << "component " << c;
}

// 2. A motion of amplitude a = 1e-6 dx: the nonlinear Elastic force differs from its linearisation by O(a^2), i.e.
// about 1e-6 of the force itself; 1e-5 allows the random field's constants. At a = 1e-3 dx the gap must be ~1000x
// larger (checked loosely: > 100x), so the comparison is not passing by being blind.
TEST(LinearLps, IsTheLinearisationOfElastic) {
  const auto L = pftest::makeLattice(7, false, kDx, 3.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto lin = linearLps();
  auto el = pftest::makeElastic(pf::Dimension::ThreeD, kE, kNu, 0.0);
  double gap[2];
  const double amp[2] = {1e-6 * kDx, 1e-3 * kDx};
  for (int k = 0; k < 2; ++k) {
    const auto y = pftest::randomMotion(L, amp[k], 17);
    const auto Fl = forceOf(*lin, L, y), Fe = forceOf(*el, L, y);
    std::vector<double> d(Fl.size());
    for (std::size_t n = 0; n < d.size(); ++n) d[n] = Fl[n] - Fe[n];
    gap[k] = maxAbs(d) / maxAbs(Fe);
  }
  EXPECT_LT(gap[0], 1e-5);
  EXPECT_GT(gap[1], 100 * gap[0]);
}

// 3. Linear: dF(du) = F(x + du) - F(x) = F(x + du), in the same arithmetic (1e-15 relative of the largest entry).
TEST(LinearLps, TangentIsTheForceOfTheIncrement) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto mat = linearLps();
  ASSERT_TRUE(mat->hasForceDerivative());
  const auto y = pftest::randomMotion(L, 1e-4 * kDx, 3);
  const auto F = forceOf(*mat, L, y);
  std::vector<double> du(y.size()), dF(y.size(), 0.0);
  for (std::size_t n = 0; n < y.size(); ++n) du[n] = y[n] - L.x[n];
  pf::StateStore st;
  st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
  ASSERT_TRUE(mat->forceDerivative(L.view(), L.x.data(), du.data(), st, dF.data()));
  for (std::size_t n = 0; n < F.size(); ++n) EXPECT_NEAR(dF[n], F[n], 1e-15 * maxAbs(F)) << "entry " << n;
}

// Peridigm's Linear LPS is 3D only; the registry takes no planar flag, so a 2D deck is refused at input.
TEST(LinearLps, HasNoPlanarOption) {
  for (const auto& p : pf::findMaterial("Linear LPS Partial Volume")->parameters)
    EXPECT_TRUE(p.name != "Plane Stress" && p.name != "Plane Strain") << p.name;
}
