// The consistent tangent of the OSB J2 models ("Elastic Plastic", "Elastic Plastic Hardening": perfect,
// isotropic, kinematic, mixed and Peridigm's law; 3D, plane stress, plane strain): forceDerivative against
// central differences of computeForce with the committed state held fixed, on whole small lattices (every
// node owned, surface nodes included, so the neighbours' return mappings feed each node's force through
// their bonds: the coupling terms are exercised), at elastic and yielding states.
//
// Step and tolerance (test StepSizeStudy prints the study): the directional step is h dy with dy a random
// field of size 1e-3 dx (a strain of order 1e-3 h). The central difference's error is C h^2 (truncation) +
// eps |F| / h (round-off, amplified by the bond sums cancelling to a small net force). Measured: the error
// falls by 100 per decade of h (h^2: 7e-5 -> 7e-7 -> 7e-9 from h = 1e-1 to 1e-3), reaches its round-off floor
// at h ~ 1e-4 and then grows as 1/h; at h = 1e-4 it is 1.6e-9 to 4.7e-9 of max |J dy| in every case.
// Tolerance 1e-6 of max |J dy|: over 200 times the measured error, while a wrong tangent misses it by orders
// of magnitude (the elastic tangent at a yielding state: 0.17 to 0.75, checked below).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/ElasticPlasticMaterial.hpp"
#include "materials/OsbGradientCorrection.hpp"

namespace {

using pf::Dimension;

constexpr double kDx = 1e-3, kRatio = 3.015, kTol = 1e-6, kStep = 1e-4;

struct Model {
  const char* name;       // for the trace
  const char* material;   // registry name
  double K, H;            // the paper's moduli (Elastic Plastic Hardening)
  double peridigmH;       // > 0: Peridigm's Hardening Modulus (3D; with its shear correction factor)
};

const Model kModels[] = {{"perfect", "Elastic Plastic", 0, 0, 0},
                         {"isotropic", "Elastic Plastic Hardening", 20e9, 0, 0},
                         {"kinematic", "Elastic Plastic Hardening", 0, 20e9, 0},
                         {"mixed", "Elastic Plastic Hardening", 20e9, 20e9, 0},
                         {"peridigm", "Elastic Plastic Hardening", 0, 0, 1e54}};
const Dimension kDims[] = {Dimension::ThreeD, Dimension::PlaneStress, Dimension::PlaneStrain};

std::unique_ptr<pf::Material> makeModel(const Model& m, Dimension dim, bool gradientCorrection = false) {
  std::map<std::string, double> v = {{"Density", 8000.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3},
                                     {"Yield Stress", 600e6}};
  if (dim == Dimension::PlaneStress) v["Plane Stress"] = 1.0;
  if (dim == Dimension::PlaneStrain) v["Plane Strain"] = 1.0;
  if (dim != Dimension::ThreeD) v["Thickness"] = kDx;
  if (std::string(m.material) == "Elastic Plastic Hardening") {
    if (m.peridigmH > 0) {
      v["Hardening Modulus"] = m.peridigmH;
      v["Apply Shear Correction Factor"] = 1.0;
    } else {
      v["Isotropic Hardening Modulus"] = m.K;
      v["Kinematic Hardening Modulus"] = m.H;
      v["Apply Shear Correction Factor"] = 0.0;
    }
  }
  if (gradientCorrection) return pf::makeMaterial(m.material, v, {{"Gradient Correction", "Quadratic"}});
  return pf::makeMaterial(m.material, v);
}

// A whole lattice with every node owned: 7^3 in 3D, 11 x 11 in 2D, delta = 3.015 dx.
pftest::Lattice lattice(Dimension dim, pf::Influence::Kind infl = pf::Influence::One) {
  const bool planar = dim != Dimension::ThreeD;
  pftest::Lattice L = pftest::makeLattice(planar ? 11 : 7, planar, kDx, kRatio, kDx, pf::Influence(infl), false);
  L.fam.unitInfluence = infl == pf::Influence::One;
  return L;
}

// y = x + s (D x + n): a homogeneous strain of direction D (uniaxial with shear, not symmetric about any
// lattice axis) plus a fixed random field n of 0.1 dx, both scaled by s, so that two values of s lie on one
// proportional path. With s = 0.006 most nodes yield (uniaxial yield strain 0.003).
std::vector<double> deformed(const pftest::Lattice& L, double s) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double D[3][3] = {{1.0, 0.4, 0.0}, {0.1, -0.3, 0.0}, {0.0, 0.0, L.planar ? 0.0 : -0.2}};
  std::vector<double> y(L.x);
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < (L.planar ? 2 : 3); ++a) {
      double d = 0.1 * kDx * u(rng);
      for (int b = 0; b < 3; ++b) d += D[a][b] * L.x[3 * p + b];
      y[3 * p + a] += s * d;
    }
  return y;
}

std::vector<double> direction(const pftest::Lattice& L, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1e-3 * kDx, 1e-3 * kDx);
  std::vector<double> dy(L.x.size(), 0.0);
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < (L.planar ? 2 : 3); ++a) dy[3 * p + a] = u(rng);
  return dy;
}

std::vector<double> force(const pftest::Lattice& L, const pf::Material& mat, pf::StateStore& st,
                          const std::vector<double>& y) {
  std::vector<double> f(y.size(), 0.0);
  mat.computeForce(L.view(), y.data(), st, f.data());
  return f;
}

// max |J dy - (F(y + h dy) - F(y - h dy)) / 2h| / max |J dy|.
double centralError(const pftest::Lattice& L, const pf::Material& mat, pf::StateStore& st,
                    const std::vector<double>& y, const std::vector<double>& dy, const std::vector<double>& Jdy,
                    double h) {
  std::vector<double> yp(y), ym(y);
  for (std::size_t k = 0; k < y.size(); ++k) { yp[k] += h * dy[k]; ym[k] -= h * dy[k]; }
  const std::vector<double> fp = force(L, mat, st, yp), fm = force(L, mat, st, ym);
  double err = 0, scale = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    err = std::max(err, std::fabs((fp[k] - fm[k]) / (2 * h) - Jdy[k]));
    scale = std::max(scale, std::fabs(Jdy[k]));
  }
  return err / scale;
}

// keeps: the material keeps its tangent (the J2 models; not the Elastic one the test compares with).
std::vector<double> tangent(const pftest::Lattice& L, const pf::Material& mat, const pf::StateStore& st,
                            const std::vector<double>& y, const std::vector<double>& dy, bool keeps = true) {
  std::vector<double> Jdy(y.size(), 0.0);
  EXPECT_TRUE(mat.forceDerivative(L.view(), y.data(), dy.data(), st, Jdy.data()));
  // The tangent kept at y (Material::makeLinearisation, what the implicit solvers apply per Krylov product) gives
  // the same bits: it is the same derivative with the work that does not depend on dy done once.
  const std::unique_ptr<pf::MaterialLinearisation> kept = mat.makeLinearisation();
  EXPECT_EQ(kept != nullptr, keeps) << "Material::makeLinearisation";
  if (kept) {
    EXPECT_TRUE(kept->update(L.view(), y.data(), st));
    std::vector<double> keptJdy(y.size(), 0.0);
    kept->apply(L.view(), dy.data(), keptJdy.data());
    int differ = 0;
    for (std::size_t k = 0; k < y.size(); ++k) differ += keptJdy[k] == Jdy[k] ? 0 : 1;
    EXPECT_EQ(differ, 0) << "components where the kept tangent differs from forceDerivative";
  }
  return Jdy;
}

// A linearisation point: committed state after s1 (none if 0), current iterate at s2.
struct Case {
  const char* name;
  double s1, s2;
  bool yields;  // most nodes return to the yield surface at s2
};

const Case kCases[] = {
    {"virgin elastic", 0.0, 0.001, false},
    {"virgin yielding", 0.0, 0.006, true},
    // committed on the yield surface (plastic at s1), loaded 0.1 % further: just past the surface
    {"at the surface, reloading", 0.006, 0.006 * 1.001, true},
    {"further yielding", 0.006, 0.009, true},
    {"elastic unloading", 0.006, 0.0055, false},
    {"reverse yielding", 0.006, -0.004, true},
};

// Number of owned nodes whose return mapping flowed at the last evaluation.
int plasticNodes(pf::StateStore& st, int n) {
  const double* lam = st.trial("Lambda");
  const double* lamN = st.committed("Lambda");
  int c = 0;
  for (int i = 0; i < n; ++i) c += lam[i] > lamN[i] ? 1 : 0;
  return c;
}

}  // namespace

TEST(PlasticTangent, MatchesCentralDifferences) {
  for (Dimension dim : kDims)
    for (const Model& m : kModels) {
      if (m.peridigmH > 0 && dim != Dimension::ThreeD) continue;  // Peridigm's law is 3D only
      const pftest::Lattice L = lattice(dim);
      auto mat = makeModel(m, dim);
      std::map<std::string, double> ev = {{"Density", 8000.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3}};
      if (dim == Dimension::PlaneStress) ev["Plane Stress"] = 1.0;
      if (dim == Dimension::PlaneStrain) ev["Plane Strain"] = 1.0;
      if (dim != Dimension::ThreeD) ev["Thickness"] = kDx;
      auto el = pf::makeMaterial("Elastic", ev);
      for (const Case& c : kCases) {
        SCOPED_TRACE(std::string(pf::toString(dim)) + " " + m.name + ": " + c.name);
        pf::StateStore st;
        st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
        if (c.s1 != 0.0) {
          force(L, *mat, st, deformed(L, c.s1));
          ASSERT_GT(plasticNodes(st, L.numQueries), L.numQueries / 2);
          st.commit();
        }
        const std::vector<double> y = deformed(L, c.s2), dy = direction(L, 5);
        force(L, *mat, st, y);
        const int plastic = plasticNodes(st, L.numQueries);
        if (c.yields) {
          EXPECT_GT(plastic, L.numQueries / 2);
        } else {
          EXPECT_EQ(plastic, 0);
        }
        const std::vector<double> Jdy = tangent(L, *mat, st, y, dy);
        const double err = centralError(L, *mat, st, y, dy, Jdy, kStep);
        // The elastic tangent at the same point: equal to the force's derivative only where no node flows.
        pf::StateStore est;
        est.allocate(el->stateSpecs(), L.numQueries, L.fam.numBonds());
        const double errElastic = centralError(L, *mat, st, y, dy, tangent(L, *el, est, y, dy, false), kStep);
        std::printf("[PlasticTangent] %-11s %-9s %-26s plastic %3d/%3d  err %.1e  (elastic tangent %.1e)\n",
                    pf::toString(dim), m.name, c.name, plastic, L.numQueries, err, errElastic);
        EXPECT_LT(err, kTol);
        if (c.yields) {
          EXPECT_GT(errElastic, 1e3 * kTol);  // the test sees a wrong plastic tangent
        }
      }
    }
}

// A non-unit influence (Gaussian omega in every term) selects the other instance of the kernels (omega read per
// bond): mixed hardening, reverse yielding. Its flow is not Eq. 52's: along t^d_tr / omega in 3D and plane strain,
// and in plane stress along t_perp / omega + phi pp x with t^d split along omega x (OsbJ2OmegaSplit.hpp), whose
// return has the extra moment sum omega x t^d V; the tangent differentiates that too. Bound kTol as above (measured
// 1.7e-9 / 2.8e-9 / 3.1e-9 in 3D / plane stress / plane strain; dropping d(sum omega x t^d V) gives 4.9e-3 in
// plane stress).
TEST(PlasticTangent, MatchesCentralDifferencesWithGaussianInfluence) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(pf::toString(dim));
    const pftest::Lattice L = lattice(dim, pf::Influence::Gaussian);
    auto mat = makeModel(kModels[3], dim);
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    force(L, *mat, st, deformed(L, 0.006));
    st.commit();
    const std::vector<double> y = deformed(L, -0.004), dy = direction(L, 9);
    force(L, *mat, st, y);
    EXPECT_GT(plasticNodes(st, L.numQueries), L.numQueries / 2);
    const double err = centralError(L, *mat, st, y, dy, tangent(L, *mat, st, y, dy), kStep);
    std::printf("[PlasticTangent] Gaussian %s: err %.1e\n", pf::toString(dim), err);
    EXPECT_LT(err, kTol);
  }
}

// `Gradient Correction` = `Quadratic` (OsbGradientCorrection.hpp): every node's bond lengths come from a least-squares
// fit over its family, so its force depends on each neighbour through the fit too; the tangent applies the same fit
// to the direction. Mixed hardening, yielding and reverse yielding, each dimension (the planar fit has 5 terms, the 3D
// one 9); every node of the small lattice is within a horizon of a face, so the fit changes every reading. Bound kTol
// as above (measured 1.9e-8 to 4.1e-8); the uncorrected tangent of the same model misses it (0.46 to 1.8; checked).
TEST(PlasticTangent, MatchesCentralDifferencesWithGradientCorrection) {
  for (Dimension dim : kDims) {
    const pftest::Lattice L = lattice(dim);
    auto mat = makeModel(kModels[3], dim, true);
    auto plain = makeModel(kModels[3], dim, false);
    for (const Case& c : {kCases[1], kCases[5]}) {
      SCOPED_TRACE(std::string(pf::toString(dim)) + ": " + c.name);
      pf::StateStore st;
      st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
      if (c.s1 != 0.0) {
        force(L, *mat, st, deformed(L, c.s1));
        st.commit();
      }
      const std::vector<double> y = deformed(L, c.s2), dy = direction(L, 11);
      force(L, *mat, st, y);
      EXPECT_GT(plasticNodes(st, L.numQueries), L.numQueries / 2);
      const double err = centralError(L, *mat, st, y, dy, tangent(L, *mat, st, y, dy), kStep);
      const double errPlain = centralError(L, *mat, st, y, dy, tangent(L, *plain, st, y, dy), kStep);
      std::printf("[PlasticTangent] gradient correction %s %s: err %.1e (uncorrected tangent %.1e)\n",
                  pf::toString(dim), c.name, err, errPlain);
      EXPECT_LT(err, kTol);
      EXPECT_GT(errPlain, 1e2 * kTol);
    }
  }
}

// The same where the correction is limited (OsbGradientCorrection.hpp, limitedCorrection): a field that is not smooth
// on the lattice scale (each node moved at random by up to 0.2 dx on top of the yielding deformation, as beside a
// prescribed line of points) makes the fitted quadratic part of many bonds a sizeable share of |xi|, where g' is well
// below 1; the tangent carries g'. Bound kTol as above; the same tangent with g' taken as 1 (the correction unlimited)
// misses it by far (checked by hand: 0.47 to 0.53).
TEST(PlasticTangent, MatchesCentralDifferencesWhereTheGradientCorrectionIsLimited) {
  for (Dimension dim : kDims) {
    const pftest::Lattice L = lattice(dim);
    auto mat = makeModel(kModels[3], dim, true);
    SCOPED_TRACE(pf::toString(dim));
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    std::vector<double> y = deformed(L, kCases[1].s2);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.2 * kDx, 0.2 * kDx);
    for (int q = 0; q < L.numNodes; ++q)
      for (int a = 0; a < (L.planar ? 2 : 3); ++a) y[3 * q + a] += u(rng);
    force(L, *mat, st, y);
    const std::vector<double> dy = direction(L, 11);
    const double err = centralError(L, *mat, st, y, dy, tangent(L, *mat, st, y, dy), kStep);
    std::printf("[PlasticTangent] limited gradient correction %s: err %.1e\n", pf::toString(dim), err);
    EXPECT_LT(err, kTol);
  }
}

// The limiter itself: g(d) = d to 1e-2 relative below 0.14 c |xi|, |g| < c |xi| always, odd, g' its derivative (central
// differences, 1e-7 relative: the difference's truncation at h = 1e-6 |xi|).
TEST(GradientCorrectionLimit, IsTheCorrectionWhenSmallBoundedAndSmooth) {
  const double xi = 2e-3, c = pf::osb::kCorrectionLimit;
  for (double d : {1e-6 * xi, 0.1 * c * xi, 0.14 * c * xi}) {
    EXPECT_NEAR(pf::osb::limitedCorrection(d, xi).value, d, 1e-2 * d);
    EXPECT_EQ(pf::osb::limitedCorrection(-d, xi).value, -pf::osb::limitedCorrection(d, xi).value);
  }
  for (double d : {0.5 * c * xi, 2.0 * c * xi, 0.6 * xi, 10.0 * xi}) {
    EXPECT_LT(std::fabs(pf::osb::limitedCorrection(d, xi).value), c * xi);
    const double h = 1e-6 * xi;
    const double fd =
        (pf::osb::limitedCorrection(d + h, xi).value - pf::osb::limitedCorrection(d - h, xi).value) / (2 * h);
    EXPECT_NEAR(pf::osb::limitedCorrection(d, xi).slope, fd, 1e-7 * std::max(1.0, fd));
  }
}

// The step-size study behind kStep and kTol: mixed hardening, reverse yielding, each dimension. The error
// must fall as h^2 while truncation dominates (a factor >= 50 of the ideal 100 per decade between h = 1e-1
// and 1e-2 and between 1e-2 and 1e-3), be below kTol at kStep, and stay within 10x of the minimum there.
TEST(PlasticTangent, StepSizeStudy) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(pf::toString(dim));
    const pftest::Lattice L = lattice(dim);
    auto mat = makeModel(kModels[3], dim);
    pf::StateStore st;
    st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
    force(L, *mat, st, deformed(L, 0.006));
    st.commit();
    const std::vector<double> y = deformed(L, 0.009), dy = direction(L, 5);
    force(L, *mat, st, y);
    const std::vector<double> Jdy = tangent(L, *mat, st, y, dy);
    std::vector<double> hs, errs;
    for (double h = 1e-1; h > 1e-9; h /= 10) {
      hs.push_back(h);
      errs.push_back(centralError(L, *mat, st, y, dy, Jdy, h));
      std::printf("[PlasticTangent] step study %s h %.0e err %.2e\n", pf::toString(dim), h, errs.back());
    }
    EXPECT_GT(errs[0] / errs[1], 50.0);
    EXPECT_GT(errs[1] / errs[2], 50.0);
    double best = errs[0];
    for (double e : errs) best = std::min(best, e);
    const double atStep = errs[static_cast<std::size_t>(std::lround(-std::log10(kStep))) - 1];
    EXPECT_LT(atStep, kTol);
    EXPECT_LT(atStep, 10.0 * best);
  }
}
