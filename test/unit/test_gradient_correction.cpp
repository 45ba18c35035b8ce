// `Gradient Correction` = `Quadratic` of the OSB J2 solid (materials/OsbGradientCorrection.hpp) against the closed
// form of what it is for: under a small quadratic displacement field u (a linearly varying strain, the bending field's
// kind), every point with a position-aware family (`Surface Correction` = `Position Aware`, which makes the dilatation
// exact for any small affine strain, truncated families included) reads the dilatation tr(eps) at itself:
//  - with the correction, at every point whose position-aware family reads an affine strain exactly (all but the
//    convex corners and edges, found by an affine field first: 275 of 343 in 3D, 117 of 121 in the plane), to the
//    field's second order (|F xi| - |xi| is nonlinear in the strain: |eps| ~ 1e-6 leaves ~1e-6 of it; measured
//    2.7e-6 / 1.9e-6); bound 1e-4 of the strain scale;
//  - without it, a point near a face reads tr(eps) at its bonds' midpoints' centroid, inside the body: off by the
//    gradient times that offset, a sizeable share of the strain scale here (measured 0.53 / 0.18; checked > 1e-2, so
//    the test tells the two apart), while the point with a symmetric family reads it either way (2e-7).
// 3D (7^3 lattice, delta = 3.015 dx) and plane strain (11^2); E = 200 GPa, nu = 0.3, dx = 1 mm; yield out of reach.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "model/PositionAwareInfluence.hpp"

namespace {

constexpr double kDx = 1e-3, kStrain = 1e-6;

std::unique_ptr<pf::Material> solid(bool planar, bool corrected) {
  std::map<std::string, double> v{{"Density", 7800.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3},
                                  {"Yield Stress", 1e15}, {"Isotropic Hardening Modulus", 0.0},
                                  {"Kinematic Hardening Modulus", 0.0}, {"Apply Shear Correction Factor", 0.0}};
  if (planar) v["Plane Strain"] = 1.0, v["Thickness"] = kDx;
  std::map<std::string, std::string> s{{"Yield Normalization", "Discrete"}};
  if (corrected) s["Gradient Correction"] = "Quadratic";
  return pf::makeMaterial("Elastic Plastic Hardening", v, s);
}

// A quadratic field with every second derivative present, u_a = s sum_bc c_abc x_b x_c, its strain ~ kStrain across
// the lattice (s = kStrain / size); tr eps(x) = s sum_a sum_d (c_aad + c_ada) x_d.
struct Field {
  double c[3][3][3] = {};  // u_a = s sum_bc c[a][b][c] x_b x_c
  double s = 0.0;
  void displacement(const double* x, double* u) const {
    for (int a = 0; a < 3; ++a) {
      u[a] = 0.0;
      for (int b = 0; b < 3; ++b)
        for (int d = 0; d < 3; ++d) u[a] += s * c[a][b][d] * x[b] * x[d];
    }
  }
  double traceStrain(const double* x, int dims) const {  // sum_a du_a/dx_a
    double t = 0.0;
    for (int a = 0; a < dims; ++a)
      for (int d = 0; d < 3; ++d) t += s * (c[a][a][d] + c[a][d][a]) * x[d];
    return t;
  }
};

Field makeField(bool planar, double size) {
  Field f;
  const int dims = planar ? 2 : 3;
  int k = 0;
  for (int a = 0; a < dims; ++a)
    for (int b = 0; b < dims; ++b)
      for (int d = 0; d < dims; ++d) f.c[a][b][d] = std::sin(1.0 + 0.7 * (k++));  // fixed, every term nonzero
  f.s = kStrain / size;  // strains ~ kStrain across the lattice
  return f;
}

struct Reading {
  double worstCorrected = 0.0, worstPlain = 0.0, worstPlainSymmetric = 0.0;
  int points = 0, total = 0;
};

Reading read(bool planar) {
  const int n = planar ? 11 : 7;
  auto L = pftest::makeLattice(n, planar, kDx, 3.015, planar ? kDx : 0.0, pf::Influence::One, false);
  pf::positionAwareInfluence(L.fam, 0, L.numQueries, L.x.data(), L.volume.data(), planar);
  pf::computeWeightedVolume(L.view(), L.m.data());
  const double size = (n - 1) * kDx;
  const Field f = makeField(planar, size);
  std::vector<double> y = L.x;
  for (int p = 0; p < L.numNodes; ++p) {
    double u[3];
    f.displacement(&L.x[3 * p], u);
    for (int a = 0; a < (planar ? 2 : 3); ++a) y[3 * p + a] += u[a];
  }
  // The points whose position-aware family reads any small affine strain exactly (all but the convex corners and
  // edges, whose omega no positive weights make isotropic): an affine field's reading, tr(eps) to 1e-6 of it.
  std::vector<bool> exact(L.numQueries, true);
  {
    auto mat = solid(planar, false);
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    std::vector<double> ya = L.x, force(y.size(), 0.0);
    const double g[3][3] = {{1.0, 0.3, -0.2}, {0.1, -0.6, 0.4}, {0.5, 0.2, 0.8}};
    for (int p = 0; p < L.numNodes; ++p)
      for (int a = 0; a < (planar ? 2 : 3); ++a)
        for (int b = 0; b < 3; ++b) ya[3 * p + a] += kStrain * g[a][b] * L.x[3 * p + b];
    mat->computeForce(L.view(), ya.data(), st, force.data());
    const double tr = kStrain * (g[0][0] + g[1][1] + (planar ? 0.0 : g[2][2]));
    for (int i = 0; i < L.numQueries; ++i) exact[i] = std::fabs(st.trial("Dilatation")[i] - tr) < 1e-6 * kStrain;
  }
  Reading r;
  r.total = L.numQueries;
  const int centre = (L.numNodes - 1) / 2;  // the lattice is symmetric about it: a whole, symmetric family
  for (bool corrected : {true, false}) {
    auto mat = solid(planar, corrected);
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    std::vector<double> force(y.size(), 0.0);
    mat->computeForce(L.view(), y.data(), st, force.data());
    const double* theta = st.trial("Dilatation");
    for (int i = 0; i < L.numQueries; ++i) {
      if (!exact[i]) continue;
      if (corrected) ++r.points;
      const double err = std::fabs(theta[i] - f.traceStrain(&L.x[3 * i], planar ? 2 : 3)) / kStrain;
      (corrected ? r.worstCorrected : r.worstPlain) = std::max(corrected ? r.worstCorrected : r.worstPlain, err);
      if (!corrected && i == centre) r.worstPlainSymmetric = err;
    }
  }
  return r;
}

TEST(GradientCorrection, EveryPointReadsTheDilatationAtItself) {
  for (bool planar : {false, true}) {
    SCOPED_TRACE(planar ? "plane strain" : "3D");
    const Reading r = read(planar);
    std::printf("[GradientCorrection] %s, %d of %d points: corrected %.2e, uncorrected %.2e (centre %.2e) of the "
                "strain scale\n", planar ? "plane strain" : "3D", r.points, r.total, r.worstCorrected, r.worstPlain,
                r.worstPlainSymmetric);
    EXPECT_LT(r.worstCorrected, 1e-4);
    EXPECT_GT(r.worstPlain, 1e-2);
    EXPECT_LT(r.worstPlainSymmetric, 1e-4);
  }
}

TEST(GradientCorrection, RefusedWithThermalExpansion) {
  std::map<std::string, double> v{{"Density", 7800.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3},
                                  {"Yield Stress", 6e8}, {"Thermal Expansion Coefficient", 1e-5}};
  try {
    pf::makeMaterial("Elastic Plastic", v, {{"Gradient Correction", "Quadratic"}});
    FAIL() << "accepted";
  } catch (const pf::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Gradient Correction'"), std::string::npos) << e.what();
  }
}

}  // namespace
