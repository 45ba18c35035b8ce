// Unit tests of "Pals" (materials/PalsMaterial: Peridigm's position-aware linear solid) against what the model
// guarantees by construction on ANY family, checked at a corner point of a cubic lattice (a one-sided family, where
// a plain OSB solid is far off) and at the centre:
//  1. the multipliers satisfy the 6 + 6 moment conditions, recomputed here from the paper's formulas
//     (Mitchell, Silling & Littlewood 2015): sum omega e_k V = (1,1,1,0,0,0), sum sigma eps_k^2 V = (2/3,2/3,2/3,2,2,2);
//  2. a small homogeneous strain gives theta = tr(eps) (any strain: the dilatation moments are all fixed);
//  3. each of the six unit strain modes gives the classical energy density K tr(eps)^2 / 2 + mu eps_dev : eps_dev
//     (the deviatoric moments fix the energy of exactly these modes).
// Units: SI; K = 67.55 GPa, mu = 25.9 GPa (the aluminium of Peridigm's Pals_Simple_Shear), dx = 1 mm, delta = 2.015 dx.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

constexpr double kK = 67.55e9, kMu = 25.9e9, kDx = 1e-3;

std::unique_ptr<pf::Material> pals() {
  return pf::makeMaterial("Pals", {{"Density", 2700.0}, {"Bulk Modulus", kK}, {"Shear Modulus", kMu}});
}

struct Evaluated {
  pf::StateStore state;
  std::vector<double> force;
};

Evaluated evaluate(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y) {
  Evaluated e;
  e.state.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  e.force.assign(3 * L.numNodes, 0.0);
  mat.computeForce(L.view(), y.data(), e.state, e.force.data());
  return e;
}

std::vector<double> strained(const pftest::Lattice& L, const double eps[3][3]) {
  std::vector<double> y = L.x;
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) y[3 * p + a] += eps[a][b] * L.x[3 * p + b];
  return y;
}

// The lattice's corner (index 0) and centre.
std::vector<int> probes(const pftest::Lattice& L) {
  const int n = static_cast<int>(std::lround(std::cbrt(L.numNodes)));
  const int c = n / 2;
  return {0, c + n * c + n * n * c};
}

}  // namespace

// 1. The moment conditions, from the stored multipliers with omega, sigma written out here (base functions One). The
// sums have ~30-120 terms of size <= max|omega| |xi|^2 V ~ 1 (the conditions' scale), so round-off stays below 1e-12.
TEST(Pals, MultipliersSatisfyTheMomentConditions) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto mat = pals();
  const Evaluated e = evaluate(*mat, L, L.x);
  const double dilTarget[6] = {1, 1, 1, 0, 0, 0}, devTarget[6] = {2.0 / 3, 2.0 / 3, 2.0 / 3, 2, 2, 2};
  for (int i : probes(L)) {
    double lam[6], tau[6];
    for (int k = 0; k < 6; ++k) {
      lam[k] = e.state.trial("Lagrange_Multiplier_Dilatation_" + std::to_string(k + 1))[i];
      tau[k] = e.state.trial("Lagrange_Multiplier_Deviatoric_" + std::to_string(k + 1))[i];
    }
    EXPECT_EQ(e.state.trial("Dilatation_Normalization")[i], 1.0);
    EXPECT_EQ(e.state.trial("Deviatoric_Normalization")[i], 1.0);
    double dil[6] = {0}, dev[6] = {0};
    for (int b = L.fam.offsets[i]; b < L.fam.offsets[i + 1]; ++b) {
      const int j = L.fam.neighbors[b];
      const double a = L.x[3 * j] - L.x[3 * i], bb = L.x[3 * j + 1] - L.x[3 * i + 1], c = L.x[3 * j + 2] - L.x[3 * i + 2];
      const double r = std::sqrt(a * a + bb * bb + c * c), V = L.volume[j];
      const double ek[6] = {a * a, bb * bb, c * c, 2 * a * bb, 2 * a * c, 2 * bb * c};
      const double dk[6] = {a * a / r - r / 3, bb * bb / r - r / 3, c * c / r - r / 3, 2 * a * bb / r, 2 * a * c / r,
                            2 * bb * c / r};
      double omega = 1.0, sigma = 1.0;
      for (int k = 0; k < 6; ++k) omega += lam[k] * ek[k], sigma += tau[k] * dk[k] * dk[k];
      for (int k = 0; k < 6; ++k) dil[k] += omega * ek[k] * V, dev[k] += sigma * dk[k] * dk[k] * V;
    }
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(dil[k], dilTarget[k], 1e-12) << "node " << i << " dilatation mode " << k;
      EXPECT_NEAR(dev[k], devTarget[k], 1e-12) << "node " << i << " deviatoric mode " << k;
    }
  }
}

// 2. theta of a homogeneous strain of size 1e-6 is tr(eps) up to the extension's second-order term (|eps|^2 ~ 1e-12
// against tr ~ 1e-6: 1e-6 relative) and round-off (|y_j - y_i| - |xi| carries ~1e-16 |xi| per bond, ~1e-10 of
// |eps| |xi|); 1e-5 relative is the bound. A model without the corner's correction (plain OSB) is off by tens of %.
TEST(Pals, HomogeneousStrainGivesItsTraceEverywhere) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  const double eps[3][3] = {{1.0e-6, 0.3e-6, -0.2e-6}, {0.3e-6, -0.4e-6, 0.5e-6}, {-0.2e-6, 0.5e-6, 0.7e-6}};
  const double tr = eps[0][0] + eps[1][1] + eps[2][2];
  auto mat = pals();
  const Evaluated e = evaluate(*mat, L, strained(L, eps));
  for (int i : probes(L)) EXPECT_NEAR(e.state.trial("Dilatation")[i], tr, 1e-5 * std::fabs(tr)) << "node " << i;
}

// 3. The six unit strain modes at 1e-6: W against K tr^2/2 + mu eps_dev:eps_dev (first-order exact; the relative
// error is of the order of the strain, 1e-6, and round-off as in 2; 1e-5 relative is the bound).
TEST(Pals, UnitModesStoreTheClassicalEnergy) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto mat = pals();
  const double g = 1e-6;
  for (int mode = 0; mode < 6; ++mode) {
    double eps[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    if (mode < 3) {
      eps[mode][mode] = g;
    } else {
      const int p = mode == 5 ? 1 : 0, q = mode == 3 ? 1 : 2;  // xy, xz, yz
      eps[p][q] = eps[q][p] = g;
    }
    double tr = eps[0][0] + eps[1][1] + eps[2][2], devdev = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double d = eps[a][b] - (a == b ? tr / 3 : 0.0);
        devdev += d * d;
      }
    const double W = 0.5 * kK * tr * tr + kMu * devdev;
    const Evaluated e = evaluate(*mat, L, strained(L, eps));
    for (int i : probes(L))
      EXPECT_NEAR(e.state.trial("Stored_Elastic_Energy_Density")[i], W, 1e-5 * W) << "mode " << mode << " node " << i;
  }
}

// A rigid motion (translation and a rotation of 0.3 rad) stores nothing and exerts no force: the extensions are 0 up
// to round-off (~1e-16 |xi|, scaled by the moduli: forces below 1e-6 of E |xi| / dx-sized terms).
TEST(Pals, RigidMotionIsForceFree) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<double> y(L.x.size());
  for (int p = 0; p < L.numNodes; ++p) {
    const double* x = &L.x[3 * p];
    y[3 * p] = c * x[0] - s * x[1] + 2e-4;
    y[3 * p + 1] = s * x[0] + c * x[1] - 1e-4;
    y[3 * p + 2] = x[2] + 3e-4;
  }
  auto mat = pals();
  const Evaluated e = evaluate(*mat, L, y);
  const double scale = kK * 1e-16 / kDx * 1e3;  // force density of a 1e-16 strain, generously x1000
  for (double f : e.force) EXPECT_NEAR(f, 0.0, scale);
}

// The influence functions are Peridigm's predefined ones; anything else is refused with the parameter named.
TEST(Pals, RefusesAnUnknownInfluenceFunction) {
  EXPECT_THROW(pf::makeMaterial("Pals", {{"Density", 2700.0}, {"Bulk Modulus", kK}, {"Shear Modulus", kMu}},
                                {{"Deviatoric Influence Function", "1.0/zeta"}}),
               pf::InputError);
}

// The exact directional derivative against central differences of the force, on a whole 5^3 lattice (corner, edge,
// face and interior families) moved by a random motion of 1e-4 dx. Step h = 1e-3 along a direction of size 1e-3 dx: the
// central difference's truncation is O(h^2) and its round-off ~1e-16 |F| / (h |dF|); measured 1.3e-10 of max |dF|, bound
// 1e-6 (leaving out the rotation term t (dY - n n.dY)/|Y| gives ~1e-4).
TEST(Pals, ForceDerivativeMatchesCentralDifferences) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto mat = pals();
  ASSERT_TRUE(mat->hasForceDerivative());
  const std::vector<double> y = pftest::randomMotion(L, 1e-4 * kDx, 7);
  std::vector<double> dir = pftest::randomMotion(L, 1e-3 * kDx, 11);
  for (std::size_t k = 0; k < dir.size(); ++k) dir[k] -= L.x[k];
  Evaluated at = evaluate(*mat, L, y);
  std::vector<double> dF(3 * L.numNodes, 0.0);
  ASSERT_TRUE(mat->forceDerivative(L.view(), y.data(), dir.data(), at.state, dF.data()));
  const double h = 1e-3;
  std::vector<double> yp(y), ym(y);
  for (std::size_t k = 0; k < y.size(); ++k) yp[k] += h * dir[k], ym[k] -= h * dir[k];
  const Evaluated fp = evaluate(*mat, L, yp), fm = evaluate(*mat, L, ym);
  double scale = 0.0, err = 0.0;
  for (std::size_t k = 0; k < dF.size(); ++k) {
    scale = std::max(scale, std::fabs(dF[k]));
    err = std::max(err, std::fabs(dF[k] - (fp.force[k] - fm.force[k]) / (2 * h)));
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(err, 1e-6 * scale) << "max |dF - central difference| = " << err << " of max |dF| = " << scale;
}

// stiffnessBound against the Jacobian's rows at the reference configuration (built column by column from the exact
// derivative, itself checked above): per node, the bound must cover sum_j |dF_i/du_j| of each of its three rows.
TEST(Pals, StiffnessBoundCoversTheJacobianRows) {
  const auto L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, /*centreOnly=*/false);
  auto mat = pals();
  Evaluated at = evaluate(*mat, L, L.x);
  const int n = 3 * L.numNodes;
  std::vector<double> rowSum(n, 0.0), dir(n, 0.0), dF(n);
  for (int col = 0; col < n; ++col) {
    dir[col] = 1.0;
    std::fill(dF.begin(), dF.end(), 0.0);
    mat->forceDerivative(L.view(), L.x.data(), dir.data(), at.state, dF.data());
    for (int r = 0; r < n; ++r) rowSum[r] += std::fabs(dF[r]);
    dir[col] = 0.0;
  }
  std::vector<double> bound(L.numNodes, 0.0);
  mat->stiffnessBound(L.view(), bound.data());
  double tightest = 1e300;
  for (int i = 0; i < L.numNodes; ++i)
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(bound[i], rowSum[3 * i + a]) << "node " << i << " row " << a;
      tightest = std::min(tightest, bound[i] / rowSum[3 * i + a]);
    }
  // A bound, not a wild overestimate (the ADR density and Verlet's step depend on it): measured 3.2 at its tightest.
  EXPECT_LT(tightest, 20.0);
}
