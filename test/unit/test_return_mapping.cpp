// Unit tests of the per-node return mapping of the OSB J2 solid by itself (materials/J2ReturnMapping.hpp),
// without bonds or a material point. Every reference is a closed form built here from the equations of
// Pirzadeh et al. 2024 ("Eq. N") and, for the 2D constants the paper prints differently, from the table of
// docs/materials.md; none calls the kernel's own constants.
// Units: SI; E = 200 GPa, nu = 0.3, sigma_y0 = 600 MPa, K and H up to 20 GPa (the paper's examples).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "materials/J2ReturnMapping.hpp"

namespace {

using pf::Dimension;
using pf::OsbJ2Constants;
using pf::OsbJ2NodeState;
using pf::OsbJ2Return;
using pf::OsbJ2Status;
using pf::OsbTrialMoments;

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 200e9, kNu = 0.3, kSy = 600e6;
constexpr double kMu = kE / (2.0 * (1.0 + kNu)), kKappa = kE / (3.0 * (1.0 - 2.0 * kNu));
constexpr double kDelta = 3e-3, kThick = 1e-3;  // horizon, 2D thickness
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNewtonTol = 1e-12;  // the kernel's default (J2Parameters::tolerance)
const Dimension kDims[] = {Dimension::ThreeD, Dimension::PlaneStrain, Dimension::PlaneStress};

const char* dimName(Dimension d) {
  return d == Dimension::ThreeD ? "3D" : d == Dimension::PlaneStrain ? "PlaneStrain" : "PlaneStress";
}

// Return-mapping constants for weighted volume m, written out from the paper and docs/materials.md:
// bm = -B of Eq. 48 (15 mu/m, 8 mu/m); psi0 = Cy sigma^2 (Eq. 45 with pi delta^5 = 5m/4 in 3D, pi h delta^4 =
// 2m in 2D, Eq. 34); a2 = coefficient of (t.x)^2 in psi (Eq. 31: 0 in 3D; 2D: 5/(2m) per docs/materials.md,
// not the printed 2/m); Ce: |d eps_p| = dlambda sqrt(Ce psi), which for 3D is Eq. 55 (A0 = 5/m, Eq. 36, and
// psi = G^2 P1/2, Eq. 49, give Ce = 2 A0), 2D per docs/materials.md; g2 per docs/materials.md (3D: does not
// enter, every 3D trial state below has t.x = 0).
OsbJ2Constants paperConstants(Dimension dim, double m, double K, double H) {
  OsbJ2Constants k{};
  if (dim == Dimension::ThreeD) {
    k.yield = {5.0 / (2.0 * m), 2.0 * (5.0 / m), 0.0};
    k.bm = 15.0 * kMu / m;
    k.g2 = 1.0;
  } else {
    k.yield = {4.0 / (3.0 * m), 16.0 / (3.0 * m), 5.0 / (2.0 * m)};
    k.bm = 8.0 * kMu / m;
    const double c = 1.0 / 3.0 + kKappa / (8.0 * kMu), kk = (1.0 - 2.0 * kNu) / (1.0 - kNu);  // OsbConstants
    k.g2 = dim == Dimension::PlaneStress ? 2.0 * (1.0 - 2.0 * c * kk) : 1.0;
  }
  k.yieldStress = kSy;
  k.isoHardening = K;
  k.kinHardening = H;
  k.tolerance = kNewtonTol;
  k.maxIterations = 10;
  return k;
}

// A synthetic family: bond lengths x, volumes V and a trial deviatoric force state t (deterministic
// pseudo-random values). 3D: t.x = 0, as for any t^d with omega = 1 (the dilatation removes it).
struct Family {
  std::vector<double> x, V, t;
  double m = 0;  // x.x = sum x^2 V (omega = 1)
};

double dot(const Family& f, const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k] * f.V[k];
  return s;
}

Family makeFamily(Dimension dim, std::uint64_t seed) {
  Family f;
  auto uniform = [&seed]() {  // LCG (Knuth), in [0, 1)
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(seed >> 11) * 0x1.0p-53;
  };
  for (int k = 0; k < 40; ++k) {
    f.x.push_back((0.5 + 2.5 * uniform()) * 1e-3);
    f.V.push_back(1e-9 * (0.5 + uniform()));
    f.t.push_back(2.0 * uniform() - 1.0);
  }
  f.m = dot(f, f.x, f.x);
  if (dim == Dimension::ThreeD) {
    const double p = dot(f, f.t, f.x) / f.m;
    for (std::size_t k = 0; k < f.t.size(); ++k) f.t[k] -= p * f.x[k];
  }
  return f;
}

// psi(t) = |t|^2/2 + a2 (t.x)^2 (Eq. 31) and the von Mises stress sqrt(psi/Cy) it stands for (Eq. 20).
double psiOf(const Family& f, const std::vector<double>& t, const OsbJ2Constants& k) {
  const double tx = dot(f, t, f.x);
  return 0.5 * dot(f, t, t) + k.yield.a2 * tx * tx;
}

// Scales t so that its von Mises stress is vm; returns the moments of the scaled state.
OsbTrialMoments scaleTo(Family& f, const OsbJ2Constants& k, double vm) {
  const double s = vm / std::sqrt(psiOf(f, f.t, k) / k.yield.Cy);
  OsbTrialMoments mo{0, 0, 0, 0, f.m};
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    const double t = f.t[i] *= s;
    mo.S2 += t * t * f.V[i];
    mo.Sx += t * f.x[i] * f.V[i];
    mo.S3 += t * t * t * f.V[i];
    mo.A3 += std::fabs(t) * t * t * f.V[i];
  }
  return mo;
}

// 3D moments of a trial state with von Mises stress vm (Eq. 20 with /2: |t|^2 = 2 Cy vm^2) and the sign of
// its third moment given by sgn (+1, -1, or 0 for pure shear).
OsbTrialMoments moments3D(const OsbJ2Constants& k, double m, double vm, double sgn) {
  const double S2 = 2.0 * k.yield.Cy * vm * vm;
  return {S2, 0.0, sgn * S2 * vm, S2 * vm, m};
}

// sigma_bar_n = sigma_y0 + K alpha_n + s q_n, s = sign(sigma_vm,signed - q_n) (Eqs. 39, 46).
double yieldLevel(const OsbJ2Constants& k, const OsbJ2NodeState& n, double signedVm) {
  const double s = signedVm - n.q >= 0.0 ? 1.0 : -1.0;
  return k.yieldStress + k.isoHardening * n.alpha + s * n.q;
}

}  // namespace

// The constants the kernel writes the yield surface with, for the paper's continuum normalisation.
TEST(ReturnMapping, YieldConstantsAreThePapers) {
  // A few roundings apart (each constant is 2-4 operations on either side, each within eps/2).
  const double tol = 8 * kEps;
  const double m3 = 0.8 * kPi * std::pow(kDelta, 5);  // Eq. 34
  const pf::OsbYieldConstants y3 = pf::osbYieldConstants(Dimension::ThreeD, m3);
  EXPECT_NEAR(y3.Cy / (25.0 / (8.0 * kPi * std::pow(kDelta, 5))), 1.0, tol);          // Eq. 45
  EXPECT_NEAR(y3.Ce / (2.0 * 25.0 / (4.0 * kPi * std::pow(kDelta, 5))), 1.0, tol);    // Ce = 2 A0, Eqs. 36, 55
  EXPECT_EQ(y3.a2, 0.0);                                                              // Eq. 31, 3D
  const double d4h = kThick * std::pow(kDelta, 4);
  const double m2 = 0.5 * kPi * d4h;  // Eq. 34
  for (Dimension dim : {Dimension::PlaneStrain, Dimension::PlaneStress}) {
    const pf::OsbYieldConstants y2 = pf::osbYieldConstants(dim, m2);
    EXPECT_NEAR(y2.Cy / (8.0 / (3.0 * kPi * d4h)), 1.0, tol);  // Eq. 45, 2D
    // docs/materials.md: 5/(pi h delta^4) makes 2D reproduce 3D J2; Eq. 31 prints 4/(pi h delta^4).
    EXPECT_NEAR(y2.a2 / (5.0 / (kPi * d4h)), 1.0, tol);
    EXPECT_NEAR(y2.Ce / (32.0 / (3.0 * kPi * d4h)), 1.0, tol);  // 16/(3m), docs/materials.md table
  }
}

// Eq. 43: f(t^d_tr) <= 0 is elastic, and then e^dp, q and alpha stay at n and t^d_n+1 = t^d_tr.
TEST(ReturnMapping, ElasticTrialStateReturnsUnchanged) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(dimName(dim));
    Family f = makeFamily(dim, 7);
    const OsbJ2Constants k = paperConstants(dim, f.m, 20e9, 20e9);
    const OsbJ2NodeState n{0.25, 2e-3, 30e6, 1.0};
    const double vm = 0.8 * kSy;  // below sigma_bar_n = sigma_y0 + K alpha_n +- q_n for either sign
    const OsbTrialMoments mo = scaleTo(f, k, vm);
    const double sgn = mo.S3 >= 0.0 ? 1.0 : -1.0;
    ASSERT_LT(vm, yieldLevel(k, n, sgn * vm));
    const OsbJ2Return r = pf::osbJ2ReturnMapping(mo, n, k);
    ASSERT_EQ(r.status, OsbJ2Status::Ok);
    EXPECT_EQ(r.dlambda, 0.0);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.plasticStrain, 0.0);
    EXPECT_EQ(r.G1, 1.0);
    EXPECT_EQ(r.G2, 1.0);
    EXPECT_EQ(r.state.lambda, n.lambda);
    EXPECT_EQ(r.state.alpha, n.alpha);
    EXPECT_EQ(r.state.q, n.q);
    EXPECT_EQ(r.vonMises, r.vonMisesTrial);
    // The moments are sums over 40 bonds: relative round-off up to ~40 eps.
    EXPECT_NEAR(r.vonMises / vm, 1.0, 64 * kEps);
  }
}

// 3D with linear hardening the return is radial and dlambda has a closed form. From Eqs. 47-48,
// G = 1/(1 + 15 mu dlambda/m), so sigma_vm,n+1 = G sigma_tr (Eq. 20); with P1 = |t_tr|^2 = 5 sigma_tr^2/m and
// A0 = 5/m (Eq. 36), Eq. 55 gives |d eps_p| = 5 dlambda G sigma_tr/m; Eqs. 46, 56, 57 give sigma_bar_n+1 =
// sigma_bar_n + (K + H) |d eps_p|; Eq. 50 (G^2 P1 = 2 psi0, i.e. sigma_vm,n+1 = sigma_bar_n+1) is then linear in
// dlambda after multiplying by 1 + 15 mu dlambda/m:
//   dlambda = m (sigma_tr - sigma_bar_n) / (15 mu sigma_bar_n + 5 (K + H) sigma_tr),
// and |d eps_p| = (sigma_tr - sigma_bar_n)/(3 mu + K + H), the classical radial return.
TEST(ReturnMapping, LinearHardening3DClosedForm) {
  const double m = 0.8 * kPi * std::pow(kDelta, 5);
  struct Case { const char* name; double K, H; OsbJ2NodeState n; double sgn, ratio; };
  const Case cases[] = {
      {"perfect", 0, 0, {0, 0, 0, 0}, 1, 1.5},
      {"iso", 20e9, 0, {3e-25, 3e-3, 0, 1}, 1, 1.5},
      {"kin", 0, 20e9, {3e-25, 3e-3, 60e6, 1}, 1, 2.0},
      {"mixed", 20e9, 20e9, {3e-25, 3e-3, 60e6, 1}, 1, 1.1},
      {"mixed, compression", 20e9, 20e9, {3e-25, 3e-3, -60e6, -1}, -1, 3.0},
      {"mixed, reversal", 10e9, 30e9, {3e-25, 3e-3, 60e6, 1}, -1, 1.5},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const OsbJ2Constants k = paperConstants(Dimension::ThreeD, m, c.K, c.H);
    // sigma_tr = ratio sigma_bar_n; the sign of the trial state sets s, which sets sigma_bar_n: iterate once.
    double sbar = yieldLevel(k, c.n, c.sgn * c.ratio * kSy);
    double vmTr = c.ratio * sbar;
    sbar = yieldLevel(k, c.n, c.sgn * vmTr);
    vmTr = c.ratio * sbar;
    ASSERT_EQ(sbar, yieldLevel(k, c.n, c.sgn * vmTr));
    const OsbJ2Return r = pf::osbJ2ReturnMapping(moments3D(k, m, vmTr, c.sgn), c.n, k);
    ASSERT_EQ(r.status, OsbJ2Status::Ok);
    const double dlam = m * (vmTr - sbar) / (15.0 * kMu * sbar + 5.0 * (c.K + c.H) * vmTr);
    const double deps = (vmTr - sbar) / (3.0 * kMu + c.K + c.H);
    const double G = 1.0 / (1.0 + 15.0 * kMu * dlam / m);
    // Newton stops at |sigma_vm - sigma_bar| <= 1e-12 sigma_tr; that residual times (1 + 15 mu dlambda/m) = 1/G
    // is linear in dlambda with slope (sigma_tr - sigma_bar_n)/dlambda, hence the relative bound below, plus
    // round-off of both sides (a few tens of operations).
    const double tol = kNewtonTol * vmTr / (G * (vmTr - sbar)) + 64 * kEps;
    EXPECT_NEAR(r.dlambda / dlam, 1.0, tol);
    EXPECT_NEAR(r.plasticStrain / deps, 1.0, tol);
    EXPECT_NEAR(r.G1 / G, 1.0, tol);
    EXPECT_NEAR(r.vonMises / (sbar + (c.K + c.H) * deps), 1.0, tol);
    // lambda_n + dlambda: one more rounding, of the sum (dlambda ~ m/mu ~ 1e-25 here, lambda_n alike).
    EXPECT_NEAR(r.state.lambda - c.n.lambda, dlam, tol * dlam + kEps * r.state.lambda);
    // docs/materials.md: in 3D the first guess is this closed form, so Newton makes no update.
    EXPECT_EQ(r.iterations, 0);
  }
}

// After a plastic return the yield function of the returned state vanishes (Eq. 44), in every dimension:
// t^d_n+1 is rebuilt bond by bond from the returned G1, G2 (Eq. 47 per part) and psi, sigma_bar_n+1 are
// evaluated from their definitions (Eqs. 31, 45, 46).
TEST(ReturnMapping, YieldFunctionVanishesAfterReturn) {
  for (Dimension dim : kDims)
    for (double ratio : {1.05, 1.5, 4.0}) {
      SCOPED_TRACE(std::string(dimName(dim)) + " ratio " + std::to_string(ratio));
      Family f = makeFamily(dim, 11);
      const OsbJ2Constants k = paperConstants(dim, f.m, 20e9, 10e9);
      const OsbJ2NodeState n{0.0, 1e-3, 20e6, 1.0};
      const double vmTr = ratio * yieldLevel(k, n, kSy);
      const OsbTrialMoments mo = scaleTo(f, k, vmTr);
      const double sgn = mo.S3 >= 0.0 ? 1.0 : -1.0, s = sgn * vmTr - n.q >= 0.0 ? 1.0 : -1.0;
      const OsbJ2Return r = pf::osbJ2ReturnMapping(mo, n, k);
      ASSERT_EQ(r.status, OsbJ2Status::Ok);
      ASSERT_GT(r.dlambda, 0.0);
      EXPECT_LE(r.iterations, k.maxIterations);
      // Eq. 47 per part: G1 = 1/(1 + bm dlambda), G2 = 1/(1 + g2 bm dlambda); a few roundings apart.
      EXPECT_NEAR(r.G1 * (1.0 + k.bm * r.dlambda), 1.0, 8 * kEps);
      EXPECT_NEAR(r.G2 * (1.0 + k.g2 * k.bm * r.dlambda), 1.0, 8 * kEps);
      const double pp = dot(f, f.t, f.x) / f.m;
      std::vector<double> t(f.t.size());
      for (std::size_t b = 0; b < t.size(); ++b) t[b] = r.G1 * (f.t[b] - pp * f.x[b]) + r.G2 * pp * f.x[b];
      const double sbar = k.yieldStress + k.isoHardening * r.state.alpha + s * r.state.q;  // Eq. 46
      const double psi0 = k.yield.Cy * sbar * sbar;                                        // Eq. 45
      // Newton's residual |sqrt(psi/Cy) - sigma_bar| <= 1e-12 sigma_tr becomes |psi - psi0|/psi0 <= 2e-12
      // sigma_tr/sigma_bar; the bond sums here and in the moments add ~40 eps each.
      EXPECT_NEAR(psiOf(f, t, k) / psi0 - 1.0, 0.0, 2 * kNewtonTol * vmTr / sbar + 256 * kEps);
      EXPECT_NEAR(r.vonMises / sbar, 1.0, kNewtonTol * vmTr / sbar + 64 * kEps);
      if (dim == Dimension::ThreeD) {  // Eq. 55: |d eps_p| = dlambda G sqrt(A0 P1), A0 = 5/m (Eq. 36)
        const double P1 = dot(f, f.t, f.t);
        EXPECT_NEAR(r.plasticStrain / (r.dlambda * r.G1 * std::sqrt(5.0 / f.m * P1)), 1.0, 64 * kEps);
      }
    }
}

// Mixed hardening: alpha takes |d eps_p| (Eq. 57), q takes s H |d eps_p| (Eq. 56) with s = sign(sigma_vm,n -
// q_n), so the yield level (Eq. 46) grows by K |d eps_p| (isotropic part) plus H |d eps_p| (kinematic part).
TEST(ReturnMapping, MixedHardeningSplitsAsEqs56And57) {
  for (Dimension dim : kDims)
    for (double sgnWanted : {1.0, -1.0}) {
      SCOPED_TRACE(std::string(dimName(dim)) + (sgnWanted > 0 ? " tension" : " compression"));
      const double K = 15e9, H = 25e9;
      Family f = makeFamily(dim, 3);
      const OsbJ2Constants k = paperConstants(dim, f.m, K, H);
      OsbTrialMoments mo = scaleTo(f, k, 1.0);
      if ((mo.S3 >= 0.0 ? 1.0 : -1.0) != sgnWanted)  // flip the state: t -> -t flips the third moment
        for (double& t : f.t) t = -t;
      const OsbJ2NodeState n{0.5, 4e-3, sgnWanted * 50e6, sgnWanted};
      const double sbarN = yieldLevel(k, n, sgnWanted * 2.0 * kSy);
      mo = scaleTo(f, k, 1.6 * sbarN);
      const double s = sgnWanted * 1.6 * sbarN - n.q >= 0.0 ? 1.0 : -1.0;
      ASSERT_EQ(s, sgnWanted);
      const OsbJ2Return r = pf::osbJ2ReturnMapping(mo, n, k);
      ASSERT_EQ(r.status, OsbJ2Status::Ok);
      EXPECT_EQ(r.state.sign, sgnWanted);
      const double deps = r.plasticStrain;
      ASSERT_GT(deps, 0.0);
      // alpha_n + |d eps_p| and q_n + s H |d eps_p| are one rounding each (<= eps/2 of the sum); undoing the
      // addition here adds at most one more, so the increments are exact to ~eps of the new value.
      const double isoInc = K * (r.state.alpha - n.alpha), kinInc = s * (r.state.q - n.q);
      EXPECT_NEAR(isoInc / (K * deps), 1.0, 4 * kEps * r.state.alpha / deps);
      EXPECT_NEAR(kinInc / (H * deps), 1.0, 4 * kEps * (std::fabs(r.state.q) + H * deps) / (H * deps));
      // Eq. 46 before and after: three terms each, a few roundings of sigma_bar.
      const double sbar = k.yieldStress + K * r.state.alpha + s * r.state.q;
      EXPECT_NEAR(sbar - sbarN, isoInc + kinInc, 16 * kEps * sbar);
      if (dim == Dimension::ThreeD) {  // the closed form of LinearHardening3DClosedForm, with its tolerance
        const double vmTr = 1.6 * sbarN, G = r.G1;
        EXPECT_NEAR(deps / ((vmTr - sbarN) / (3.0 * kMu + K + H)), 1.0,
                    kNewtonTol * vmTr / (G * (vmTr - sbarN)) + 64 * kEps);
      }
    }
}

// The sign of sigma_vm is that of the third moment of t^d (docs/materials.md, "Open choices"); when it
// vanishes (pure shear) the committed sign is kept, and a virgin point counts as +1.
TEST(ReturnMapping, VonMisesSignFromThirdMoment) {
  const double m = 0.8 * kPi * std::pow(kDelta, 5);
  const OsbJ2Constants k = paperConstants(Dimension::ThreeD, m, 0, 0);
  const double vm = 0.5 * kSy;  // elastic: only the sign is at stake
  auto signOf = [&](double thirdMomentSign, double committed) {
    return pf::osbJ2ReturnMapping(moments3D(k, m, vm, thirdMomentSign), {0, 0, 0, committed}, k).state.sign;
  };
  EXPECT_EQ(signOf(1.0, -1.0), 1.0);
  EXPECT_EQ(signOf(-1.0, 1.0), -1.0);
  EXPECT_EQ(signOf(0.0, -1.0), -1.0);
  EXPECT_EQ(signOf(0.0, 1.0), 1.0);
  EXPECT_EQ(signOf(0.0, 0.0), 1.0);
}

// Kinematic hardening, a point hardened along + (q = 0.7 sigma_y) and unloading along the same direction to vm =
// 0.4 sigma_y: sigma_vm,signed - q < 0 but |sigma_vm,signed - q| = 0.3 sigma_y < sigma_y, so the state is elastic
// (it was returned as plastic to sigma_y - q until 2026-12-06). The same vm reversed (sign -) is 1.1 sigma_y from q:
// it yields, and returns onto |sigma_vm,signed - q| = sigma_y with q reduced (Eqs. 45-46, 56).
TEST(ReturnMapping, UnloadingPastTheBackStressStaysElastic) {
  const double m = 0.8 * kPi * std::pow(kDelta, 5);
  const double H = 20e9, q = 0.7 * kSy;
  const OsbJ2Constants k = paperConstants(Dimension::ThreeD, m, 0, H);
  const OsbJ2NodeState n{1e-3, q / H, q, 1.0};
  const OsbJ2Return along = pf::osbJ2ReturnMapping(moments3D(k, m, 0.4 * kSy, 1.0), n, k);
  ASSERT_EQ(along.status, OsbJ2Status::Ok);
  EXPECT_EQ(along.dlambda, 0.0);
  EXPECT_EQ(along.state.q, q);
  EXPECT_EQ(along.state.alpha, n.alpha);
  const OsbJ2Return against = pf::osbJ2ReturnMapping(moments3D(k, m, 0.4 * kSy, -1.0), n, k);
  ASSERT_EQ(against.status, OsbJ2Status::Ok);
  EXPECT_GT(against.dlambda, 0.0);
  EXPECT_LT(against.state.q, q);
  EXPECT_NEAR((against.vonMises + against.state.q) / kSy, 1.0, 1e-9);  // |-vm - q| = sigma_y (K = 0)
}

// OsbJ2SignRule::CommittedThirdMoment (plane stress's rule in the kernels): a point with a back stress
// (q = 0.7 sigma_y, committed along +) whose trial third moment passes through zero at vm = 0.4 sigma_y. With the
// paper's rule the return jumps there, elastic on one side and yielding on the other (|-vm - q| = 1.1 sigma_y): the
// force is not continuous in the displacement. With the committed sign both sides return the same state (elastic;
// the stored sign follows S3, for the output and the next step), and once that sign is committed the reversed
// trial state yields as the paper's return does. Exact equalities: the same arithmetic on the same inputs.
TEST(ReturnMapping, ThirdMomentFlipWithBackStressActsFromTheNextStep) {
  const double m = 0.8 * kPi * std::pow(kDelta, 5);
  const double H = 20e9, q = 0.7 * kSy;
  OsbJ2Constants paper = paperConstants(Dimension::ThreeD, m, 0, H);
  OsbJ2Constants lagged = paper;
  lagged.signRule = pf::OsbJ2SignRule::CommittedThirdMoment;
  const OsbJ2NodeState n{1e-3, q / H, q, 1.0};
  const OsbTrialMoments plus = moments3D(paper, m, 0.4 * kSy, 1e-3), minus = moments3D(paper, m, 0.4 * kSy, -1e-3);
  // The paper's rule: the jump.
  EXPECT_EQ(pf::osbJ2ReturnMapping(plus, n, paper).dlambda, 0.0);
  EXPECT_GT(pf::osbJ2ReturnMapping(minus, n, paper).dlambda, 0.0);
  // The committed sign: no jump.
  const OsbJ2Return a = pf::osbJ2ReturnMapping(plus, n, lagged), b = pf::osbJ2ReturnMapping(minus, n, lagged);
  EXPECT_EQ(a.dlambda, 0.0);
  EXPECT_EQ(b.dlambda, 0.0);
  EXPECT_EQ(a.vonMises, b.vonMises);
  EXPECT_EQ(a.G1, b.G1);
  EXPECT_EQ(b.state.q, q);
  EXPECT_EQ(a.state.sign, 1.0);
  EXPECT_EQ(b.state.sign, -1.0);
  // The next step, from the committed flipped sign: the paper's reverse yield.
  const OsbJ2NodeState flipped{n.lambda, n.alpha, n.q, b.state.sign};
  const OsbJ2Return next = pf::osbJ2ReturnMapping(minus, flipped, lagged);
  const OsbJ2Return ref = pf::osbJ2ReturnMapping(minus, n, paper);
  EXPECT_GT(next.dlambda, 0.0);
  EXPECT_EQ(next.dlambda, ref.dlambda);
  EXPECT_EQ(next.state.q, ref.state.q);
  // Without a back stress the sign does not enter the returned state's force: the current S3 is used as before.
  const OsbJ2NodeState hardened{1e-3, 1e-3, 0.0, 1.0};
  const OsbJ2Return c = pf::osbJ2ReturnMapping(moments3D(paper, m, 1.2 * kSy, -1.0), hardened, lagged),
                    d = pf::osbJ2ReturnMapping(moments3D(paper, m, 1.2 * kSy, -1.0), hardened, paper);
  EXPECT_EQ(c.state.q, d.state.q);
  EXPECT_EQ(c.dlambda, d.dlambda);
}

// Failures come back as a status (the bond loop turns them into ConstitutiveFailure).
TEST(ReturnMapping, FailuresAreStatuses) {
  const double m = 0.8 * kPi * std::pow(kDelta, 5);
  const OsbJ2Constants k3 = paperConstants(Dimension::ThreeD, m, 0, 20e9);
  // |q| beyond sigma_y0 + K alpha: sigma_bar_n = sigma_y0 + s q_n < 0 (Eq. 46), the scalar model has no meaning.
  const OsbJ2Return bad = pf::osbJ2ReturnMapping(moments3D(k3, m, 2 * kSy, 1.0), {0, 0, -700e6, 1}, k3);
  EXPECT_EQ(bad.status, OsbJ2Status::BackStressBeyondYield);
  EXPECT_LT(bad.yieldLevel, 0.0);
  // Plane stress needs Newton updates (G1 != G2, docs/materials.md): none allowed -> not converged.
  Family f = makeFamily(Dimension::PlaneStress, 5);
  OsbJ2Constants k2 = paperConstants(Dimension::PlaneStress, f.m, 20e9, 0);
  k2.maxIterations = 0;
  const OsbJ2NodeState n{0, 0, 0, 0};
  const OsbJ2Return r = pf::osbJ2ReturnMapping(scaleTo(f, k2, 2.0 * kSy), n, k2);
  EXPECT_EQ(r.status, OsbJ2Status::NotConverged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_NEAR(r.vonMisesTrial / (2.0 * kSy), 1.0, 64 * kEps);
}
