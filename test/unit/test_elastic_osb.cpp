// Unit tests of the elastic ordinary state-based (OSB) kernel (materials/OsbKernels, OsbConstants,
// ElasticMaterial) in 3D, plane stress and plane strain -- issue 2, "Must show":
//  1. weighted volume and dilatation of interior points against closed forms for affine fields;
//  2. classical (Hooke) stress reproduced by the peridynamic stress of an interior point;
//  3. zero force under large rigid motions of a whole body (surface nodes included);
//  4. internal force = -grad(strain energy), by central finite differences;
//  5. osbStiffnessBound bounds the finite-difference row sums of the force Jacobian.
// Units: SI; E = 200 GPa, nu = 0.3 (0.25 in one set), dx = 1 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "LatticeFixture.hpp"
#include "materials/OsbKernels.hpp"
#include "core/StateStore.hpp"

namespace {

using pf::Dimension;
using pf::Influence;
using pftest::Lattice;
using pftest::makeElastic;
using pftest::makeLattice;
using Mat3 = std::array<double, 9>;  // row-major 3x3

constexpr double kE = 200e9, kNu = 0.3, kDx = 1e-3, kH = 2e-3;  // thickness kH for the planar models
constexpr double kPi = 3.14159265358979323846;
const Dimension kDims[3] = {Dimension::ThreeD, Dimension::PlaneStress, Dimension::PlaneStrain};

// y = c + R x + H x (R and H row-major 3x3; c a translation).
std::vector<double> mapAffine(const Lattice& L, const Mat3& F, const double* c = nullptr) {
  std::vector<double> y(3 * L.numNodes);
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < 3; ++a) {
      double s = c ? c[a] : 0.0;
      for (int b = 0; b < 3; ++b) s += F[3 * a + b] * L.x[3 * p + b];
      y[3 * p + a] = s;
    }
  return y;
}
Mat3 identityPlus(const Mat3& H) {
  Mat3 F = H;
  F[0] += 1; F[4] += 1; F[8] += 1;
  return F;
}

// Force density of every node of L from the material's own computeForce (the production path).
std::vector<double> materialForce(const Lattice& L, const pf::ElasticMaterial& mat, const std::vector<double>& y) {
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  std::vector<double> f(3 * L.numNodes, 0.0);
  mat.computeForce(L.view(), y.data(), st, f.data());
  return f;
}

double maxAbs(const std::vector<double>& v) {
  double r = 0;
  for (double a : v) r = std::max(r, std::fabs(a));
  return r;
}

// ---------------------------------------------------------------------------------------------------
// 0. The lattice families themselves (buildFamilies on 3D and on planar z = 0 point sets)
// ---------------------------------------------------------------------------------------------------

TEST(ElasticOsbLattice, BuildFamiliesOnPlanarPoints) {
  // Every planar (2D) model has all points at z = 0. The centre of a 7 x 7 lattice with
  // delta = 3.015 dx has the 28 lattice points 0 < i^2 + j^2 <= 9 as neighbours (3D: 122).
  for (bool planar : {false, true}) {
    std::vector<double> pts;
    const int nz = planar ? 1 : 7;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 7; ++i) pts.insert(pts.end(), {(i - 3) * kDx, (j - 3) * kDx, planar ? 0.0 : (k - 3) * kDx});
    const int centre = planar ? 24 : 171;
    for (int d = 0; d < 3; ++d) std::swap(pts[d], pts[3 * centre + d]);
    pf::BondFamily fam;
    pf::buildFamilies(pts, 1, {3.015 * kDx}, fam);
    EXPECT_EQ(fam.offsets[1], planar ? 28 : 122) << (planar ? "planar z = 0 point set" : "3D point set");
  }
}

// ---------------------------------------------------------------------------------------------------
// 1. Weighted volume and dilatation
// ---------------------------------------------------------------------------------------------------

TEST(ElasticOsbWeightedVolume, ConvergesToContinuumValue) {
  // omega = 1: continuum m = 4 pi delta^5 / 5 (3D), pi h delta^4 / 2 (2D slab of thickness h).
  for (bool planar : {false, true}) {
    double err[2];
    const double ratios[2] = {3.015, 10.0};
    for (int r = 0; r < 2; ++r) {
      const double delta = ratios[r] * kDx;
      const int n = 2 * static_cast<int>(std::ceil(ratios[r])) + 1;
      const Lattice L = makeLattice(n, planar, kDx, ratios[r], kH, Influence::One, true);
      const double mc = planar ? kPi * kH * std::pow(delta, 4) / 2 : 4 * kPi * std::pow(delta, 5) / 5;
      const double ratio = L.m[0] / mc;
      err[r] = std::fabs(ratio - 1);
      std::printf("[ElasticOsb] %s delta/dx=%.3f: %d bonds, m_discrete/m_continuum = %.6f\n",
                  planar ? "2D" : "3D", ratios[r], L.fam.offsets[1], ratio);
    }
    // The discrete sum converges to the integral as delta/dx grows (error from the cells cut by the
    // sphere/circle |xi| = delta, O(dx/delta)); measured m_discrete/m_continuum: 3D 1.1307 -> 0.9924,
    // 2D 1.0478 -> 1.0194 (delta/dx 3.015 -> 10).
    EXPECT_LT(err[1], err[0]) << (planar ? "2D" : "3D");
    // 3 % at delta/dx = 10: measured 0.76 % (3D) and 1.94 % (2D) -- the 2D disc has far fewer points
    // (316) than the 3D ball (4168), so its lattice-count noise is larger; 3 % is ~1.5x the 2D value.
    EXPECT_LT(err[1], 0.03) << (planar ? "2D" : "3D");
  }
}

// Closed-form dilatation of an isotropic in-plane/3D stretch y = (1 + eps) X: e = eps |xi| exactly,
// so theta = k D eps for any lattice and any omega.
double isotropicTheta(Dimension d, double nu, double eps) {
  switch (d) {
    case Dimension::ThreeD: return 3 * eps;                                // tr(eps I)
    case Dimension::PlaneStrain: return 2 * eps;                           // in-plane trace
    case Dimension::PlaneStress: return (1 - 2 * nu) / (1 - nu) * 2 * eps;  // 3D volume strain, s_zz = 0
  }
  return 0;
}

// The kernels pack the overlap nodes into records; a view that does not say how many there are must be
// refused, not read past its arrays.
TEST(ElasticOsbKernels, ViewWithoutNodeCountIsRefused) {
  const Lattice L = makeLattice(5, false, kDx, 1.5, kH, Influence::One, false);
  auto mat = makeElastic(Dimension::ThreeD, kE, kNu, kH);
  std::vector<double> theta(L.numNodes, 0.0), force(3 * L.numNodes, 0.0);
  pf::FamilyView v = L.view();
  ASSERT_EQ(v.numNodes, L.numNodes);
  pf::osbDilatation(v, mat->constants(), L.x.data(), nullptr, theta.data());
  EXPECT_NEAR(theta[0], 0.0, 1e-12);  // undeformed
  v.numNodes = 0;
  EXPECT_THROW(pf::osbDilatation(v, mat->constants(), L.x.data(), nullptr, theta.data()), std::logic_error);
  EXPECT_THROW(pf::osbElasticDilatationAndForce(v, mat->constants(), L.x.data(), theta.data(), force.data()),
               std::logic_error);
}

TEST(ElasticOsbDilatation, IsotropicStretchIsExact) {
  const double eps = 1e-6;
  for (double ratio : {3.015, 10.0})
    for (Influence infl : {Influence::One, Influence::ParabolicDecay})
      for (Dimension d : kDims) {
        const bool planar = pf::isPlanar(d);
        const int n = 2 * static_cast<int>(std::ceil(ratio)) + 1;
        const Lattice L = makeLattice(n, planar, kDx, ratio, kH, infl, true);
        auto mat = makeElastic(d, kE, kNu, kH);
        Mat3 H{};
        H[0] = H[4] = eps;
        if (!planar) H[8] = eps;
        const std::vector<double> y = mapAffine(L, identityPlus(H));
        std::vector<double> theta(L.numNodes, 0.0);
        pf::osbDilatation(L.view(), mat->constants(), y.data(), nullptr, theta.data());
        const double expect = isotropicTheta(d, kNu, eps);
        // |Y| - |xi| cancels ~6 of 16 digits at eps = 1e-6 (relative error of each e ~ 1e-16/1e-6),
        // so theta is exact up to ~1e-10 relative; 1e-8 leaves margin and still rejects any wrong
        // constant (k, D) or volume weighting, which would be an O(1) relative error.
        EXPECT_NEAR(theta[0], expect, 1e-8 * std::fabs(expect))
            << pf::toString(d) << " delta/dx=" << ratio << " influence=" << static_cast<int>(infl.kind);
      }
}

TEST(ElasticOsbDilatation, GeneralAffineMatchesTrace) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (double ratio : {3.015, 10.0})
    for (Dimension d : kDims) {
      const bool planar = pf::isPlanar(d);
      const int n = 2 * static_cast<int>(std::ceil(ratio)) + 1;
      const Lattice L = makeLattice(n, planar, kDx, ratio, kH, Influence::One, true);
      auto mat = makeElastic(d, kE, kNu, kH);
      const pf::OsbConstants& c = mat->constants();
      for (int trial = 0; trial < 5; ++trial) {
        Mat3 H{};
        const int nd = planar ? 2 : 3;
        for (int a = 0; a < nd; ++a)
          for (int b = a; b < nd; ++b) H[3 * a + b] = H[3 * b + a] = 1e-6 * U(rng);
        double trace = 0, frob2 = 0;
        for (int a = 0; a < 3; ++a) trace += H[4 * a];
        for (double h : H) frob2 += h * h;
        const std::vector<double> y = mapAffine(L, identityPlus(H));
        std::vector<double> theta(L.numNodes, 0.0);
        pf::osbDilatation(L.view(), c, y.data(), nullptr, theta.data());
        // Linear limit: e = xi.H.xi/|xi| + O(|H|^2 |xi|), and sum omega |xi|^2 n(x)n V = (m/D) I on a
        // cubic/square lattice (the lattice symmetry makes the 2nd moment isotropic), so
        // theta = k tr(H) (3D: tr H; plane strain: in-plane tr; plane stress: (1-2nu)/(1-nu) tr).
        const double expect = c.k * trace;
        // Tolerance: |e/|xi| - n.H.n| <= |H|_F^2 (second-order Taylor term of |(I+H)n| - 1), giving
        // |theta - k tr H| <= k D |H|_F^2 (~1e-12 here), plus 1e-8 |H| for the |Y| - |xi| round-off.
        // A wrong constant would be off by O(|H|) = O(1e-6).
        const double tol = c.k * c.D * frob2 + 1e-8 * std::sqrt(frob2);
        EXPECT_NEAR(theta[0], expect, tol) << pf::toString(d) << " delta/dx=" << ratio;
        if (trial == 0)
          std::printf("[ElasticOsb] %s delta/dx=%.3f affine: theta=%.9e  k trH=%.9e  |diff|/|H|=%.2e\n",
                      pf::toString(d), ratio, theta[0], expect, std::fabs(theta[0] - expect) / std::sqrt(frob2));
      }
    }
}

// ---------------------------------------------------------------------------------------------------
// 2. Classical stress reproduction
// ---------------------------------------------------------------------------------------------------

// Peridynamic stress of node 0 (the lattice centre, whose family is complete):
//   sigma = sum_j T<xi_j> (x) xi_j V_j,  T = t M  (M = Y/|Y|).
// It is read off the kernel's own output: running osbElasticForce on node 0 alone adds
// f_j -= t_0j V_0 M_0j to every neighbour j, so t_0j M_0j = -f_j / V_0.
Mat3 pdStressOfCentre(const Lattice& L, const pf::OsbConstants& c, const std::vector<double>& y) {
  const pf::FamilyView v = L.view(0, 1);
  std::vector<double> theta(L.numNodes, 0.0), f(3 * L.numNodes, 0.0);
  pf::osbDilatation(v, c, y.data(), nullptr, theta.data());
  pf::osbElasticForce(v, c, y.data(), theta.data(), f.data());
  Mat3 s{};
  for (int b = L.fam.offsets[0]; b < L.fam.offsets[1]; ++b) {
    const int j = L.fam.neighbors[b];
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        s[3 * a + e] += (-f[3 * j + a] / L.volume[0]) * (L.x[3 * j + e] - L.x[e]) * L.volume[j];
  }
  return s;
}

// Hooke's law for the small strain eps: 3D sigma = lambda tr(eps) I + 2 mu eps; plane strain: the
// in-plane block of the same (eps_zz = 0); plane stress (sigma_zz = 0): E/(1-nu^2)[(1-nu) eps + nu tr I]
// = 2 mu eps + E nu/(1-nu^2) tr I in-plane.
Mat3 hooke(Dimension d, double E, double nu, const Mat3& eps) {
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double lam = d == Dimension::PlaneStress ? E * nu / (1 - nu * nu) : lambda;
  const double tr = eps[0] + eps[4] + eps[8];
  Mat3 s{};
  for (int k = 0; k < 9; ++k) s[k] = 2 * mu * eps[k];
  for (int a = 0; a < 3; ++a) s[4 * a] += lam * tr;
  if (pf::isPlanar(d)) s[2] = s[5] = s[6] = s[7] = s[8] = 0.0;  // in-plane block only
  return s;
}

TEST(ElasticOsbStress, ReproducesHookeAtLargeHorizon) {
  const double ratio = 10.0, amp = 1e-6;
  const Lattice L3 = makeLattice(21, false, kDx, ratio, kH, Influence::One, true);
  const Lattice L2 = makeLattice(21, true, kDx, ratio, kH, Influence::One, true);
  double worst = 0;
  for (double nu : {0.3, 0.25})
    for (Dimension d : kDims) {
      const Lattice& L = pf::isPlanar(d) ? L2 : L3;
      auto mat = makeElastic(d, kE, nu, kH);
      // uniaxial, pure shear (xy), general symmetric strain (with out-of-plane terms in 3D)
      std::vector<std::pair<const char*, Mat3>> cases = {
          {"uniaxial", Mat3{1, 0, 0, 0, 0, 0, 0, 0, 0}},
          {"shear", Mat3{0, 1, 0, 1, 0, 0, 0, 0, 0}},
          {"general", pf::isPlanar(d) ? Mat3{0.8, -0.3, 0, -0.3, -0.5, 0, 0, 0, 0}
                                      : Mat3{0.8, -0.3, 0.4, -0.3, -0.5, 0.2, 0.4, 0.2, 0.6}}};
      for (auto& cs : cases) {
        Mat3 eps = cs.second;
        for (double& e : eps) e *= amp;
        const Mat3 s = pdStressOfCentre(L, mat->constants(), mapAffine(L, identityPlus(eps)));
        const Mat3 h = hooke(d, kE, nu, eps);
        double num = 0, den = 0;
        for (int k = 0; k < 9; ++k) { num += (s[k] - h[k]) * (s[k] - h[k]); den += h[k] * h[k]; }
        const double rel = std::sqrt(num / den);
        worst = std::max(worst, rel);
        std::printf("[ElasticOsb] stress %-12s nu=%.2f %-8s |sigma_pd - sigma_hooke|/|sigma_hooke| = %.3e"
                    "  (xx: %.6e vs %.6e)\n", pf::toString(d), nu, cs.first, rel, s[0], h[0]);
        // The isotropic (2nd-moment) parts are exact on the lattice; the only error is the cubic/square
        // anisotropy of the 4th moment M4 = sum omega |xi|^2 n n n n V (see KernelMatchesLatticeMoments,
        // which prints it): at delta = 10 dx the shear-moment defect 15 M_xxyy/m - 1 is +0.94 % (3D) and
        // 8 M_xxyy/m - 1 = +4.77 % (2D: the square lattice is markedly less isotropic; the value is the
        // same at delta = 10.015 dx, so it is not a horizon tie effect), and the measured
        // errors equal these (max 0.94 % 3D, 4.77 % 2D, both for shear). Bounds: 1.5 % (3D), 6 % (2D).
        // The exact check of the constants is ConstantsGiveHookeForIsotropicMoments and, for the planar
        // kernel itself, PlanarOrientationAverageIsHooke.
        const double bound = pf::isPlanar(d) ? 0.06 : 0.015;
        EXPECT_LT(rel, bound) << pf::toString(d) << " nu=" << nu << " " << cs.first;
      }
    }
  std::printf("[ElasticOsb] worst stress error at delta/dx=10: %.3e\n", worst);
}

// The same stress predicted exactly for the lattice in the linear limit, from its own moments
// M2_ab = sum omega x^2 n_a n_b V and M4_abcd = sum omega x^2 n_a n_b n_c n_d V:
//   theta = k D/m M2:eps,  sigma = (A - B c) theta M2/m + B/m M4:eps.
// Hooke is recovered when M2 = m I/D and M4 = m (I I + 2 sym)/(D(D+2)); the difference between the
// two is the lattice anisotropy, printed here as the 4th-moment defects 5 M_xxxx/m - 1 (3D; 8/3 in
// 2D) and 15 M_xxyy/m - 1 (3D; 8 in 2D).
Mat3 latticeStress(const Lattice& L, const pf::OsbConstants& c, const Mat3& eps, double* defects = nullptr,
                   bool isotropicM4 = false) {
  double M2[9] = {}, M4[81] = {};
  for (int b = L.fam.offsets[0]; b < L.fam.offsets[1]; ++b) {
    const int j = L.fam.neighbors[b];
    const double x = L.fam.refLength[b], w = L.fam.influence[b] * x * x * L.volume[j];
    double n[3];
    for (int a = 0; a < 3; ++a) n[a] = (L.x[3 * j + a] - L.x[a]) / x;
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e) {
        M2[3 * a + e] += w * n[a] * n[e];
        for (int f = 0; f < 3; ++f)
          for (int g = 0; g < 3; ++g) M4[27 * a + 9 * e + 3 * f + g] += w * n[a] * n[e] * n[f] * n[g];
      }
  }
  const double m = L.m[0];
  if (isotropicM4) {  // replace M4 by its isotropic projection m/(D(D+2)) (d_ab d_cd + d_ac d_bd + d_ad d_bc)
    const int nd = static_cast<int>(c.D);
    for (int k = 0; k < 81; ++k) {
      const int a = k / 27, b = (k / 9) % 3, cc = (k / 3) % 3, dd = k % 3;
      auto del = [nd](int p, int q) { return (p == q && p < nd) ? 1.0 : 0.0; };
      M4[k] = m / (c.D * (c.D + 2)) * (del(a, b) * del(cc, dd) + del(a, cc) * del(b, dd) + del(a, dd) * del(b, cc));
    }
  }
  double theta = 0;
  for (int k = 0; k < 9; ++k) theta += c.k * c.D / m * M2[k] * eps[k];
  Mat3 s{};
  for (int a = 0; a < 3; ++a)
    for (int e = 0; e < 3; ++e) {
      double d = 0;
      for (int k = 0; k < 9; ++k) d += M4[9 * (3 * a + e) + k] * eps[k];
      s[3 * a + e] = (c.A - c.B * c.c) * theta * M2[3 * a + e] / m + c.B / m * d;
    }
  if (defects) {
    const double iso = c.D * (c.D + 2);
    defects[0] = iso / 3 * M4[0] / m - 1;   // M_xxxx: isotropic value 3 m/(D(D+2))
    defects[1] = iso * M4[4] / m - 1;  // M_xxyy (index 27a+9b+3c+d): isotropic m/(D(D+2))
  }
  return s;
}

TEST(ElasticOsbStress, KernelMatchesLatticeMomentsExactly) {
  // Separates "the kernel implements t" (tight) from "the constants give Hooke" (lattice-limited).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (double ratio : {3.015, 10.0})
    for (Influence infl : {Influence::One, Influence::ParabolicDecay})
      for (Dimension d : kDims) {
        const bool planar = pf::isPlanar(d);
        const int n = 2 * static_cast<int>(std::ceil(ratio)) + 1;
        const Lattice L = makeLattice(n, planar, kDx, ratio, kH, infl, true);
        auto mat = makeElastic(d, kE, kNu, kH);
        Mat3 eps{};
        for (int a = 0; a < (planar ? 2 : 3); ++a)
          for (int b = a; b < (planar ? 2 : 3); ++b) eps[3 * a + b] = eps[3 * b + a] = 1e-6 * U(rng);
        const Mat3 s = pdStressOfCentre(L, mat->constants(), mapAffine(L, identityPlus(eps)));
        double defects[2];
        const Mat3 p = latticeStress(L, mat->constants(), eps, defects);
        double num = 0, den = 0;
        for (int k = 0; k < 9; ++k) { num += (s[k] - p[k]) * (s[k] - p[k]); den += p[k] * p[k]; }
        const double rel = std::sqrt(num / den);
        if (infl == Influence::One && d != Dimension::PlaneStrain)
          std::printf("[ElasticOsb] %s delta/dx=%.3f: kernel vs lattice-moment stress %.2e; 4th-moment "
                      "defects xxxx %+.4f xxyy %+.4f\n", planar ? "2D" : "3D", ratio, rel, defects[0], defects[1]);
        // Only the geometric nonlinearity (O(|eps|) = 1e-6 relative) and round-off separate the two.
        EXPECT_LT(rel, 1e-5) << pf::toString(d) << " delta/dx=" << ratio;
      }
}

const std::pair<const char*, Mat3> kStrainShapes3D[] = {
    {"uniaxial", Mat3{1, 0, 0, 0, 0, 0, 0, 0, 0}},
    {"shear", Mat3{0, 1, 0, 1, 0, 0, 0, 0, 0}},
    {"general", Mat3{0.8, -0.3, 0.4, -0.3, -0.5, 0.2, 0.4, 0.2, 0.6}}};
const std::pair<const char*, Mat3> kStrainShapes2D[] = {
    {"uniaxial", Mat3{1, 0, 0, 0, 0, 0, 0, 0, 0}},
    {"shear", Mat3{0, 1, 0, 1, 0, 0, 0, 0, 0}},
    {"general", Mat3{0.8, -0.3, 0, -0.3, -0.5, 0, 0, 0, 0}}};

double relDiff(const Mat3& s, const Mat3& h) {
  double num = 0, den = 0;
  for (int k = 0; k < 9; ++k) { num += (s[k] - h[k]) * (s[k] - h[k]); den += h[k] * h[k]; }
  return std::sqrt(num / den);
}

TEST(ElasticOsbStress, ConstantsGiveHookeForIsotropicMoments) {
  // The OsbConstants (A, B, c, k, D) pinned exactly: the t of OsbConstants.hpp evaluated with the
  // lattice's own M2 (isotropic by symmetry) and the isotropic projection of M4 must be Hooke's law,
  // for every dimension, nu and strain. Only arithmetic round-off remains: 1e-10.
  const Lattice L3 = makeLattice(7, false, kDx, 3.015, kH, Influence::One, true);
  const Lattice L2 = makeLattice(7, true, kDx, 3.015, kH, Influence::One, true);
  for (double nu : {0.3, 0.25, 0.45})
    for (Dimension d : kDims) {
      const bool planar = pf::isPlanar(d);
      auto mat = makeElastic(d, kE, nu, kH);
      for (const auto& cs : planar ? kStrainShapes2D : kStrainShapes3D) {
        Mat3 eps = cs.second;
        for (double& e : eps) e *= 1e-6;
        const double rel = relDiff(latticeStress(planar ? L2 : L3, mat->constants(), eps, nullptr, true),
                                   hooke(d, kE, nu, eps));
        EXPECT_LT(rel, 1e-10) << pf::toString(d) << " nu=" << nu << " " << cs.first;
      }
    }
}

TEST(ElasticOsbStress, PlanarOrientationAverageIsHooke) {
  // On a square lattice the anisotropic part of M4 varies as cos(4 phi) with the strain orientation,
  // so the average of the kernel's stress over strain orientations 0 and 45 degrees (rotated back) has
  // an exactly isotropic M4 and must equal Hooke's law (plane stress / plane strain) up to the
  // geometric nonlinearity O(|eps|) = 1e-6: tolerance 1e-5. This checks the planar kernel + constants
  // directly, at delta = 3.015 dx and 10 dx and for both influence functions.
  const double c45 = std::sqrt(0.5);
  const Mat3 R{c45, -c45, 0, c45, c45, 0, 0, 0, 1};
  auto rot = [](const Mat3& Q, const Mat3& A, bool transposeFirst) {  // Q A Q^T or Q^T A Q
    Mat3 out{};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) {
            const double qa = transposeFirst ? Q[3 * p + a] : Q[3 * a + p];
            const double qb = transposeFirst ? Q[3 * q + b] : Q[3 * b + q];
            out[3 * a + b] += qa * A[3 * p + q] * qb;
          }
    return out;
  };
  for (double ratio : {3.015, 10.0})
    for (Influence infl : {Influence::One, Influence::ParabolicDecay}) {
      const int n = 2 * static_cast<int>(std::ceil(ratio)) + 1;
      const Lattice L = makeLattice(n, true, kDx, ratio, kH, infl, true);
      for (double nu : {0.3, 0.25})
        for (Dimension d : {Dimension::PlaneStress, Dimension::PlaneStrain}) {
          auto mat = makeElastic(d, kE, nu, kH);
          for (const auto& cs : kStrainShapes2D) {
            Mat3 eps = cs.second;
            for (double& e : eps) e *= 1e-6;
            const Mat3 s0 = pdStressOfCentre(L, mat->constants(), mapAffine(L, identityPlus(eps)));
            const Mat3 eR = rot(R, eps, true);  // R^T eps R
            const Mat3 s1 = rot(R, pdStressOfCentre(L, mat->constants(), mapAffine(L, identityPlus(eR))), false);
            Mat3 avg;
            for (int k = 0; k < 9; ++k) avg[k] = 0.5 * (s0[k] + s1[k]);
            const double rel = relDiff(avg, hooke(d, kE, nu, eps));
            if (infl == Influence::One && cs.first[0] == 'g')
              std::printf("[ElasticOsb] %s nu=%.2f delta/dx=%.3f: orientation-averaged stress vs Hooke %.2e "
                          "(single orientation %.2e)\n", pf::toString(d), nu, ratio, rel,
                          relDiff(s0, hooke(d, kE, nu, eps)));
            EXPECT_LT(rel, 1e-5) << pf::toString(d) << " nu=" << nu << " delta/dx=" << ratio << " " << cs.first;
          }
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// 3. Rigid motions of a whole body produce no force
// ---------------------------------------------------------------------------------------------------

Mat3 rotation(const double* axis, double angle) {  // Rodrigues
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double k[3] = {axis[0] / n, axis[1] / n, axis[2] / n};
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3 R;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) R[3 * a + b] = (a == b ? c : 0.0) + (1 - c) * k[a] * k[b];
  R[1] -= s * k[2]; R[2] += s * k[1];
  R[3] += s * k[2]; R[5] -= s * k[0];
  R[6] -= s * k[1]; R[7] += s * k[0];
  return R;
}

TEST(ElasticOsbRigidMotion, ZeroForceOnWholeBody) {
  for (Dimension d : kDims) {
    const bool planar = pf::isPlanar(d);
    const Lattice L = makeLattice(7, planar, kDx, 3.015, kH, Influence::One, false);
    auto mat = makeElastic(d, kE, kNu, kH);
    // force scale: a uniform 1e-3 stretch of the same body (the surface nodes carry its resultant)
    Mat3 S{};
    S[0] = S[4] = 1e-3;
    if (!planar) S[8] = 1e-3;
    const double scale = maxAbs(materialForce(L, *mat, mapAffine(L, identityPlus(S))));
    ASSERT_GT(scale, 0.0);
    const double axis3[3] = {1.0, 2.0, 3.0}, axisZ[3] = {0.0, 0.0, 1.0};
    // translation of the order of the body size: larger offsets only add round-off in y_j - y_i
    // (eps_machine |y| / (1e-3 |xi|) per bond), not physics.
    const double shift[3] = {2.5e-3, -4e-3, planar ? 0.0 : 1.5e-3};
    for (double deg : {0.0, 30.0, 90.0}) {
      const Mat3 R = rotation(planar ? axisZ : axis3, deg * kPi / 180);
      const std::vector<double> f = materialForce(L, *mat, mapAffine(L, R, shift));
      const double rel = maxAbs(f) / scale;
      std::printf("[ElasticOsb] rigid %-12s rotation %4.0f deg + translation: max|f| / f(1e-3 strain) = %.2e\n",
                  pf::toString(d), deg, rel);
      // A rigid motion keeps every |Y| = |xi| up to round-off ~1e-16 |y|, i.e. ~1e-13 of the extension
      // of a 1e-3 strain; 1e-10 leaves three decades for summation over ~120 bonds per node.
      EXPECT_LE(rel, 1e-10) << pf::toString(d) << " " << deg << " deg";
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// 4. Internal force = -grad(strain energy)
// ---------------------------------------------------------------------------------------------------

// Strain energy of the generic OSB form (sum over the owned nodes of L):
//   W = sum_i V_i [ (A - B c) theta_i^2 / (2 k D) + B/(2 m_i) sum_j omega e_ij^2 V_j ],
//   theta_i = k D / m_i sum_j omega x e V_j.
// Since d theta_i / d e_ij = k D omega x V_j / m_i,
//   dW/de_ij = V_i [ (A - B c) theta_i omega x / m_i + B omega e_ij / m_i ] V_j = V_i t_ij V_j,
// with t = A theta omega x/m + B omega (e - c theta x)/m as in OsbConstants.hpp. (3D check: with
// e^d = e - theta x/3, sum omega (e^d)^2 V = sum omega e^2 V - m theta^2/9, so W_i = kappa theta^2/2 +
// 15 mu/(2m) sum omega (e^d)^2 V, the classical LPS energy.) NOTE: the first term has no factor m_i;
// with (A - Bc) m_i theta_i^2/(2kD) the derivative would carry an extra factor m_i.
// e is evaluated as (|Y|^2 - |xi|^2)/(|Y| + |xi|) with |Y|^2 - |xi|^2 = (2 xi + du).du to avoid the
// cancellation in |Y| - |xi|, which keeps the finite differences below clean.
double strainEnergy(const Lattice& L, const pf::OsbConstants& c, const std::vector<double>& u) {
  double W = 0;
  std::vector<double> e;
  for (int i = 0; i < L.numQueries; ++i) {
    const int b0 = L.fam.offsets[i], b1 = L.fam.offsets[i + 1];
    e.resize(b1 - b0);
    double sx = 0, se2 = 0;
    for (int b = b0; b < b1; ++b) {
      const int j = L.fam.neighbors[b];
      double q = 0, y2 = 0;
      for (int a = 0; a < 3; ++a) {
        const double xi = L.x[3 * j + a] - L.x[3 * i + a], du = u[3 * j + a] - u[3 * i + a];
        q += (2 * xi + du) * du;
        y2 += (xi + du) * (xi + du);
      }
      const double x = L.fam.refLength[b];
      const double eb = q / (std::sqrt(y2) + x);
      const double w = L.fam.influence[b], Vj = L.volume[j];
      sx += w * x * eb * Vj;
      se2 += w * eb * eb * Vj;
    }
    const double m = L.m[i];
    const double theta = c.k * c.D * sx / m;
    W += L.volume[i] * ((c.A - c.B * c.c) * theta * theta / (2 * c.k * c.D) + c.B / (2 * m) * se2);
  }
  return W;
}

std::vector<double> randomDisplacement(const Lattice& L, double amp, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> u(3 * L.numNodes, 0.0);
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < (L.planar ? 2 : 3); ++a) u[3 * p + a] = amp * U(rng);
  return u;
}

std::vector<double> plus(const Lattice& L, const std::vector<double>& u) {
  std::vector<double> y(L.x);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] += u[k];
  return y;
}

TEST(ElasticOsbEnergy, ForceIsMinusEnergyGradient) {
  for (Influence infl : {Influence::One, Influence::ParabolicDecay})
    for (Dimension d : kDims) {
      const bool planar = pf::isPlanar(d);
      const Lattice L = makeLattice(planar ? 9 : 7, planar, kDx, 3.015, kH, infl, false);
      auto mat = makeElastic(d, kE, kNu, kH);
      const pf::OsbConstants& c = mat->constants();
      std::vector<double> u = randomDisplacement(L, 1e-4 * kDx, 11);
      const std::vector<double> f = materialForce(L, *mat, plus(L, u));
      const double h = 1e-7 * kDx;
      double maxErr = 0, maxF = 0;
      for (int i = 0; i < L.numNodes; ++i)
        for (int a = 0; a < (planar ? 2 : 3); ++a) {
          const double u0 = u[3 * i + a];
          u[3 * i + a] = u0 + h;
          const double Wp = strainEnergy(L, c, u);
          u[3 * i + a] = u0 - h;
          const double Wm = strainEnergy(L, c, u);
          u[3 * i + a] = u0;
          const double dW = (Wp - Wm) / (2 * h);
          maxErr = std::max(maxErr, std::fabs(f[3 * i + a] * L.volume[i] + dW));
          maxF = std::max(maxF, std::fabs(f[3 * i + a] * L.volume[i]));
        }
      const double rel = maxErr / maxF;
      std::printf("[ElasticOsb] energy %-12s influence=%s: max|f V + dW/du| / max|f V| = %.2e\n",
                  pf::toString(d), infl == Influence::One ? "One" : "1-(r/delta)^2", rel);
      // Central differences: truncation h^2/6 W''' ~ (h/dx)^2 ~ 1e-14 relative (W is smooth on the
      // scale of a bond length); round-off eps_machine |W| / (h |grad W|) ~ 1e-10 at amplitude 1e-4 dx.
      // 1e-6 is far above both and far below any inconsistency of the force with W (O(1)).
      EXPECT_LT(rel, 1e-6) << pf::toString(d);
    }
}

// ---------------------------------------------------------------------------------------------------
// 5. osbStiffnessBound bounds sum_j |dF_i/du_j|
// ---------------------------------------------------------------------------------------------------

TEST(ElasticOsbStiffnessBound, BoundsFiniteDifferenceRowSums) {
  struct Case { Dimension d; Influence infl; double nu; };
  const Case cases[] = {{Dimension::ThreeD, Influence::One, 0.3},       {Dimension::ThreeD, Influence::ParabolicDecay, 0.3},
                        {Dimension::PlaneStress, Influence::One, 0.3},  {Dimension::PlaneStrain, Influence::One, 0.3},
                        {Dimension::PlaneStress, Influence::ParabolicDecay, 0.25},
                        {Dimension::PlaneStrain, Influence::ParabolicDecay, 0.25}};
  for (const Case& cs : cases) {
    const bool planar = pf::isPlanar(cs.d);
    const Lattice L = makeLattice(planar ? 9 : 7, planar, kDx, 3.015, kH, cs.infl, false);
    auto mat = makeElastic(cs.d, kE, cs.nu, kH);
    std::vector<double> bound(L.numNodes, 0.0);
    mat->stiffnessBound(L.view(), bound.data());
    std::vector<double> u = randomDisplacement(L, 1e-4 * kDx, 23);
    const int nc = planar ? 2 : 3;
    const double h = 1e-7 * kDx;
    // row sums sum_{j,b} |dF_{i,a}/du_{j,b}| by central differences, column by column. The step
    // makes the FD error ~ eps_machine |xi| / h ~ 2e-9 relative (round-off of |Y| - |xi|); the
    // geometric (large-deformation) part of K is O(1e-4) of the material part at this amplitude.
    std::vector<double> rowAbs(3 * L.numNodes, 0.0);
    for (int j = 0; j < L.numNodes; ++j)
      for (int b = 0; b < nc; ++b) {
        const double u0 = u[3 * j + b];
        u[3 * j + b] = u0 + h;
        const std::vector<double> fp = materialForce(L, *mat, plus(L, u));
        u[3 * j + b] = u0 - h;
        const std::vector<double> fm = materialForce(L, *mat, plus(L, u));
        u[3 * j + b] = u0;
        for (int k = 0; k < 3 * L.numNodes; ++k) rowAbs[k] += std::fabs((fp[k] - fm[k]) / (2 * h));
      }
    double worst = 0, worstInterior = 0;
    int worstNode = -1, worstComp = -1;
    for (int i = 0; i < L.numNodes; ++i)
      for (int a = 0; a < nc; ++a) {
        const double r = rowAbs[3 * i + a] / bound[i];
        if (r > worst) { worst = r; worstNode = i; worstComp = a; }
        bool interior = true;
        for (int q = 0; q < nc; ++q) interior = interior && std::fabs(L.x[3 * i + q]) < 1e-3 * kDx;
        if (interior) worstInterior = std::max(worstInterior, r);
      }
    std::printf("[ElasticOsb] bound %-12s infl=%s nu=%.2f: max_i,a rowsum|K|/bound = %.4f (node %d comp %d, "
                "x=(%.0f,%.0f,%.0f) dx), centre node %.4f\n",
                pf::toString(cs.d), cs.infl == Influence::One ? "One" : "Parab", cs.nu, worst, worstNode, worstComp,
                L.x[3 * worstNode] / kDx, L.x[3 * worstNode + 1] / kDx, L.x[3 * worstNode + 2] / kDx, worstInterior);
    // The bound must hold for every node and component: ratio <= 1 (the FD error, ~1e-8, is far
    // below any meaningful violation, so no extra allowance is given).
    // KNOWN FAILURE (reported to the lead, kernel not edited here): measured max ratios 1.013 (3D, One),
    // 0.938 (3D, parabolic), 1.337 (plane stress, One), 1.098 (plane strain, One), 1.193 / 1.570
    // (plane stress / strain, parabolic, nu = 0.25); interior (centre) nodes 0.88 / 0.73 / 1.18 / 0.95 /
    // 0.99 / 1.26. Cause: per component a, the direct bond stiffness B omega V/m n n^T contributes
    // sum_b |n_a n_b| (off-diagonal blocks) + n_a^2 (diagonal block), averaging 1 + 1/pi = 1.32 in 2D
    // (2/3 + 4/(3 pi) = 1.09 in 3D) per unit of what the bound counts; near surfaces m_j < m_i also
    // makes the t_ji term exceed B/m_i.
    EXPECT_LE(worst, 1.0) << pf::toString(cs.d) << " bound violated by factor " << worst;
  }
}

}  // namespace
