// Unit tests of "Drucker Prager Correspondence" (materials/DruckerPragerPlasticity,
// DruckerPragerCorrespondenceMaterial) with the constants of Li & Geng's Table 2 (E 30 MPa, nu 0.25,
// phi 35 deg, c 60 kPa, m0 0.2), on an interior material point driven by an affine motion:
//  1. triaxial paths (confinement, then pure shear or axial compression; 3D and plane strain),
//     associated and non-associated, with and without hardening, and an extension path that reaches the
//     apex: von Mises and mean stress and the PIV at every step against ClassicalDruckerPrager.hpp (a
//     general-purpose principal-stress return written independently, numerically differentiated flow);
//  2. before yield the stress is Hooke's law exactly; yield starts at the analytic strain;
//  3. a 90 degree rotation superposed during plastic flow changes no scalar output (1e-10);
//  4. the cubic of Eq. A15 with B4 corrected vanishes at the update's dlambda (the printed B4 does not);
//     phi = 0 is von Mises with the yield stress 2 c m;
//  5. input rules: one error line naming the parameter for each bad value; no plane stress.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "ClassicalDruckerPrager.hpp"
#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/DruckerPragerPlasticity.hpp"

namespace {

using pf::Mat3;
constexpr double kE = 30e6, kNu = 0.25, kPhi = 35.0, kC = 60e3, kM0 = 0.2;

std::map<std::string, double> values(double h, double d0, bool planeStrain) {
  std::map<std::string, double> v = {{"Density", 2000.0}, {"Young's Modulus", kE}, {"Poisson's Ratio", kNu},
                                     {"Hourglass Coefficient", 0.0}, {"Friction Angle", kPhi}, {"Cohesion", kC},
                                     {"Initial Hardening Parameter", kM0}, {"Hardening Rate", h},
                                     {"Dilatancy Ratio", d0}};
  if (planeStrain) v["Plane Strain"] = 1.0, v["Thickness"] = 1e-3;
  return v;
}
std::unique_ptr<pf::Material> dp(double h, double d0, bool planeStrain = false) {
  return pf::makeMaterial("Drucker Prager Correspondence", values(h, d0, planeStrain));
}
std::array<double, 9> diag(const std::array<double, 3>& l) { return {l[0], 0, 0, 0, l[1], 0, 0, 0, l[2]}; }

// Principal stretches of a path at step k of n per phase: phase 1 (k <= n) the confinement, phase 2 the loading.
enum class Path { ConfineShear, ConfineAxial, ExtendShear, UniaxialExtension };
std::array<double, 3> stretches(Path p, bool planar, int k, int n) {
  const double t1 = std::min(k, n) / double(n), t2 = std::max(k - n, 0) / double(n);
  const double e3 = planar ? 0.0 : 1.0;
  switch (p) {
    case Path::ConfineShear: {  // volumetric compression to 1 % strain per axis, then pure shear to 5 %
      const double c = 1 - 0.01 * t1, g = 1 + 0.05 * t2;
      return {c * g, c / g, 1 - 0.01 * t1 * e3};
    }
    case Path::ConfineAxial: {  // the same confinement, then axial compression by 5 %
      const double c = 1 - 0.01 * t1;
      return {c * (1 - 0.05 * t2), c, 1 - 0.01 * t1 * e3};
    }
    case Path::ExtendShear: {  // volumetric extension to 0.3 % (past the apex's 0.14 %), then pure shear
      const double c = 1 + 0.003 * t1, g = 1 + 0.02 * t2;
      return {c * g, c / g, 1 + 0.003 * t1 * e3};
    }
    case Path::UniaxialExtension:  // 2 % in one axis: the trial passes the apex region
      return {1 + 0.02 * (k / (2.0 * n)), 1, 1};
  }
  return {1, 1, 1};
}

}  // namespace

// 1. Both integrate the same backward-Euler law on the same strain increments (the kinematics' midpoint
//    increment (l1 - l0)/((l1 + l0)/2) per axis), so they differ only by the reference's finite-difference
//    flow direction (relative error ~1e-8, ClassicalDruckerPrager.hpp) and both solves' tolerances. Bound 1e-6 of the
//    stress scale: well inside the 1 %, and 1e4 times the measured difference would still pass
//    a real error in the return (a wrong dlambda moves the stress by its own size).
TEST(DruckerPragerCorrespondence, TriaxialPathsMatchClassicalReturn) {
  struct Case { Path path; bool planar; double h, d0; const char* name; bool apex; };
  const Case cases[] = {
      {Path::ConfineShear, false, 0.0, 1.0, "confine+shear, associated, h 0", false},
      {Path::ConfineShear, false, 0.0, 0.0, "confine+shear, d0 0, h 0 (Table 2 test 2 flow)", false},
      {Path::ConfineShear, false, 25.0, 0.3, "confine+shear, d0 0.3, h 25", false},
      {Path::ConfineAxial, false, 50.0, 1.0, "confine+axial, associated, h 50", false},
      {Path::ConfineAxial, false, 0.0, 0.5, "confine+axial, d0 0.5, h 0", false},
      {Path::ConfineShear, true, 25.0, 1.0, "plane strain confine+shear, associated, h 25", false},
      {Path::ConfineAxial, true, 0.0, 0.0, "plane strain confine+axial, d0 0, h 0", false},
      {Path::ExtendShear, false, 25.0, 0.5, "extension past the apex, then shear, d0 0.5, h 25", true},
      {Path::ExtendShear, false, 0.0, 1.0, "extension past the apex, then shear, associated", true},
      {Path::UniaxialExtension, false, 0.0, 0.3, "uniaxial extension to the apex, d0 0.3", true},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    auto mat = dp(c.h, c.d0, c.planar);
    pf::MaterialPoint mp(*mat, 1e-3, 3.0, 1e-3);
    dpref::Reference ref{dpref::law(kE, kNu, kPhi, kC, kM0, c.h, c.d0)};
    const int n = 100;
    int apexSteps = 0, plasticSteps = 0;
    double worst = 0;
    for (int k = 1; k <= 2 * n; ++k) {
      const auto l0 = stretches(c.path, c.planar, k - 1, n), l1 = stretches(c.path, c.planar, k, n);
      mp.deform(diag(l1));
      mp.evaluate();
      dpref::V3 de;
      for (int a = 0; a < 3; ++a) de[a] = (l1[a] - l0[a]) / (0.5 * (l1[a] + l0[a]));
      const double xiBefore = ref.xi;
      ref.step(de);
      apexSteps += ref.apex, plasticSteps += ref.xi > xiBefore;
      const double scale = std::max({ref.vm(), std::fabs(ref.mean()), kC});
      const double vm = mp.value("Von_Mises_Stress"), p = mp.value("Mean_Stress");
      worst = std::max({worst, std::fabs(vm - ref.vm()) / scale, std::fabs(p - ref.mean()) / scale});
      ASSERT_NEAR(vm, ref.vm(), 1e-6 * scale) << "step " << k;
      ASSERT_NEAR(p, ref.mean(), 1e-6 * scale) << "step " << k;
      ASSERT_NEAR(mp.value("Equivalent_Plastic_Strain"), ref.xi, 1e-6 * (ref.xi + 1e-6)) << "step " << k;
      ASSERT_NEAR(mp.value("Hardening_Parameter"), ref.hard(ref.xi), 1e-9) << "step " << k;
      mp.commit();
    }
    std::printf("  %-55s end: von Mises %9.3f kPa, mean %9.3f kPa, xi %.5f, plastic steps %3d, apex steps %3d, "
                "worst rel. diff %.1e\n", c.name, ref.vm() / 1e3, ref.mean() / 1e3, ref.xi, plasticSteps, apexSteps, worst);
    EXPECT_GT(plasticSteps, 50);                 // the comparison is about plastic flow
    if (c.apex) EXPECT_GT(apexSteps, 0);         // and these paths do reach the apex
    else EXPECT_EQ(apexSteps, 0);
  }
}

// 2a. Below yield the update is Hooke's law on the summed increments: tau = K tr(e) I + 2 G dev(e), to
//     round-off: F of the lattice sums is exact to 1e-13 (test_correspondence.cpp, test 1), so each of the
//     3 increments carries up to 1e-13 of strain, times the largest modulus K + 4G/3 (measured: 6e-8 Pa).
TEST(DruckerPragerCorrespondence, ElasticIsHookeBeforeYield) {
  const double K = kE / (3 * (1 - 2 * kNu)), G = kE / (2 * (1 + kNu));
  for (bool planar : {false, true}) {
    auto mat = dp(25.0, 0.5, planar);
    pf::MaterialPoint mp(*mat, 1e-3, 3.0, 1e-3);
    std::array<double, 3> e{0, 0, 0}, l0{1, 1, 1};
    for (int k = 1; k <= 3; ++k) {
      const std::array<double, 3> l1{1 - 1e-4 * k, 1 + 0.5e-4 * k, planar ? 1.0 : 1 - 0.3e-4 * k};
      for (int a = 0; a < 3; ++a) e[a] += (l1[a] - l0[a]) / (0.5 * (l1[a] + l0[a]));
      mp.deform(diag(l1)), mp.evaluate();
      if (k < 3) mp.commit();  // the last is read before a commit (commit leaves stale trial values)
      l0 = l1;
    }
    const double tr = e[0] + e[1] + e[2];
    const char* names[3] = {"Unrotated_Cauchy_StressXX", "Unrotated_Cauchy_StressYY", "Unrotated_Cauchy_StressZZ"};
    for (int a = 0; a < 3; ++a) {
      const double hooke = K * tr + 2 * G * (e[a] - tr / 3);
      EXPECT_NEAR(mp.value(names[a]), hooke, 3 * 1e-13 * (K + 4 * G / 3)) << names[a];
    }
    EXPECT_EQ(mp.value("Equivalent_Plastic_Strain"), 0.0);
    EXPECT_EQ(mp.value("Hardening_Parameter"), kM0);
  }
}

// 2b. Yield onset in uniaxial compressive strain d (one step from rest): J = 2 G |d| / sqrt(3) and
//     I = 3 K |d| (compression positive), so f = 0 at |d|* = m0 B / (2 G / sqrt(3) - 3 K A m0) (Eq. 38).
//     1e-6 below: no plastic strain, stress is Hooke's; 1e-6 above: plastic, and the stress on f = 0.
TEST(DruckerPragerCorrespondence, YieldStartsAtAnalyticStrain) {
  const double K = kE / (3 * (1 - 2 * kNu)), G = kE / (2 * (1 + kNu)), phi = kPhi * M_PI / 180;
  const double A = 2 * std::sin(phi) / (std::sqrt(3.0) * (3 - std::sin(phi)));
  const double B = 6 * kC * std::cos(phi) / (std::sqrt(3.0) * (3 - std::sin(phi)));
  const double dStar = kM0 * B / (2 * G / std::sqrt(3.0) - 3 * K * A * kM0);
  std::printf("  uniaxial-strain yield at |d| = %.6e (axial stress %.3f kPa)\n", dStar, (K + 4 * G / 3) * dStar / 1e3);
  for (double factor : {1 - 1e-6, 1 + 1e-6}) {
    auto mat = dp(0.0, 0.3);
    pf::MaterialPoint mp(*mat, 1e-3, 3.0);
    const double d = dStar * factor, l = (1 - d / 2) / (1 + d / 2);  // midpoint increment (l - 1)/((l + 1)/2) = -d
    mp.deform(diag({l, 1, 1})), mp.evaluate();
    const double sxx = mp.value("Unrotated_Cauchy_StressXX"), syy = mp.value("Unrotated_Cauchy_StressYY");
    const double J = std::fabs(sxx - syy) / std::sqrt(3.0), I = -(sxx + 2 * syy);
    if (factor < 1) {
      EXPECT_EQ(mp.value("Equivalent_Plastic_Strain"), 0.0);
      EXPECT_NEAR(sxx, -(K + 4 * G / 3) * d, 1e-12 * K * d);  // round-off of F and the increment
    } else {
      EXPECT_GT(mp.value("Equivalent_Plastic_Strain"), 0.0);
      // The overshoot of J is 1e-6 of J* ~ 2 G d* / sqrt(3); xi = dlambda / 2 ~ that / (2 G): below 1e-6 d*.
      EXPECT_LT(mp.value("Equivalent_Plastic_Strain"), 1e-6 * dStar);
      EXPECT_NEAR(J, kM0 * (A * I + B), 1e-10 * B);                      // on the yield surface
    }
  }
}

// 3. Confinement then shear with h 25, d0 0.5: at step 120 (plastic flow) the stretch is held for one step,
//    with or without a 90 degree rotation about a skew axis, then the shear goes on (rotated or not). Every
//    scalar output and the unrotated stress agree to 1e-10 relative (the existing correspondence bound:
//    round-off of the Flanagan-Taylor update over the steps).
TEST(DruckerPragerCorrespondence, SuperposedRotationDuringFlowIsObjective) {
  const double n[3] = {0.0, 0.6, 0.8};
  Mat3 Q = {0, -n[2], n[1], n[2], 0, -n[0], -n[1], n[0], 0};  // 90 degrees: Q = [n]x + n n^T
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Q[3 * i + j] += n[i] * n[j];
  auto run = [&](bool rotate, std::map<std::string, double>& out) {
    auto mat = dp(25.0, 0.5);
    pf::MaterialPoint mp(*mat, 1e-3, 3.0);
    for (int k = 1; k <= 141; ++k) {
      const int s = k <= 120 ? k : k - 1;  // step 121 holds
      Mat3 F = diag(stretches(Path::ConfineShear, false, s, 100));
      if (rotate && k >= 121) F = pf::mul(Q, F);
      mp.deform(F), mp.evaluate();
      if (k < 141) mp.commit();
    }
    for (const char* f : {"Von_Mises_Stress", "Mean_Stress", "Equivalent_Plastic_Strain", "Hardening_Parameter",
                          "Unrotated_Cauchy_StressXX", "Unrotated_Cauchy_StressYY", "Unrotated_Cauchy_StressXY",
                          "Unrotated_Cauchy_StressYZ"})
      out[f] = mp.value(f);
  };
  EXPECT_NEAR(pf::det(Q), 1.0, 1e-14);
  EXPECT_NEAR(pf::trace(Q), 1.0, 1e-14);
  std::map<std::string, double> a, b;
  run(false, a);
  run(true, b);
  EXPECT_GT(a["Equivalent_Plastic_Strain"], 1e-3);
  const double scale = a["Von_Mises_Stress"];
  for (const auto& kv : a) {
    const bool stress = kv.first.find("Stress") != std::string::npos;
    EXPECT_NEAR(b[kv.first], kv.second, 1e-10 * (stress ? scale : std::fabs(kv.second))) << kv.first;
  }
}

// 4. The cubic of Eq. A15 (coefficients A16-A17, B4 corrected) at the update's dlambda vanishes to the
//    round-off of its terms (1e-10 of the largest |B_i dl^(3-i)|); with the printed B4 (alpha13 J_tr
//    instead of alpha13^2 J_tr) it does not (alpha13 = 1 - m0 + h xi_n = 1.05 here: a 5 % term).
TEST(DruckerPragerCorrespondence, CubicOfA15WithCorrectedB4) {
  const double K = kE / (3 * (1 - 2 * kNu)), G = kE / (2 * (1 + kNu)), xiN = 0.01, h = 25.0;
  const pf::DruckerPragerLaw law = pf::druckerPragerLaw(kPhi, kC, kM0, h, 0.5);
  const Mat3 tauN = {-400e3, 0, 0, 0, -300e3, 0, 0, 0, -300e3};
  const Mat3 de = {-2e-2, 4e-3, 0, 4e-3, 5e-3, 0, 0, 0, 0};
  const pf::DruckerPragerStep s = pf::druckerPragerUpdate(law, K, G, tauN, xiN, de);
  ASSERT_GT(s.dlambda, 0.0);
  ASSERT_FALSE(s.apex);
  // Trial invariants (compression positive) computed here from Hooke's law.
  const double tr = de[0] + de[4] + de[8];
  Mat3 sig = tauN;
  for (int c = 0; c < 9; ++c) sig[c] += 2 * G * de[c];
  for (int c : {0, 4, 8}) sig[c] += (K - 2 * G / 3) * tr;
  const double I = -(sig[0] + sig[4] + sig[8]), p = -I / 3;
  double ss = 0;
  for (int c = 0; c < 9; ++c) {
    const double v = sig[c] - ((c % 4 == 0) ? p : 0.0);
    ss += v * v;
  }
  const double J = std::sqrt(0.5 * ss);
  double b[4];
  pf::druckerPragerCubic(law, K, G, I, J, xiN, b);
  const double x = s.dlambda, terms[4] = {b[0] * x * x * x, b[1] * x * x, b[2] * x, b[3]};
  double big = 0, sum = 0;
  for (double t : terms) big = std::max(big, std::fabs(t)), sum += t;
  EXPECT_LT(std::fabs(sum), 1e-10 * big);
  const double a13 = 1 - kM0 + h * xiN, printedB4 = b[3] - a13 * a13 * J + a13 * J;
  EXPECT_GT(std::fabs(sum - b[3] + printedB4), 1e-3 * big);
}

// 4b. phi = 0 makes A = 0: a pressure-independent cone (a von Mises cylinder) with yield J = m B, B = 2c/sqrt(3),
//     i.e. von Mises stress 2 c m. Perfectly plastic (h = 0) pure shear after confinement ends on that value
//     exactly (round-off of the return, 1e-12), whatever d0 (no apex, no dilatancy: A d0 = 0); m0 = 1 is
//     admitted and keeps m = 1.
TEST(DruckerPragerCorrespondence, ZeroFrictionIsVonMisesWithYield2cm) {
  for (double m0 : {0.2, 1.0}) {
    auto v = values(0.0, 0.7, false);
    v["Friction Angle"] = 0.0, v["Initial Hardening Parameter"] = m0;
    auto mat = pf::makeMaterial("Drucker Prager Correspondence", v);
    pf::MaterialPoint mp(*mat, 1e-3, 3.0);
    for (int k = 1; k <= 200; ++k) {
      mp.deform(diag(stretches(Path::ConfineShear, false, k, 100))), mp.evaluate();
      if (k < 200) mp.commit();
    }
    EXPECT_GT(mp.value("Equivalent_Plastic_Strain"), 0.01);
    EXPECT_NEAR(mp.value("Von_Mises_Stress"), 2 * kC * m0, 1e-12 * kC) << "m0 " << m0;
    EXPECT_EQ(mp.value("Hardening_Parameter"), m0);
  }
}

// 5. Bad values: one line naming the parameter. Dilatancy Ratio 0 is accepted (Table 2, tests 1-6).
TEST(DruckerPragerCorrespondence, InputRules) {
  auto refusedNaming = [](std::map<std::string, double> v, const std::string& name) {
    try {
      pf::makeMaterial("Drucker Prager Correspondence", v);
      ADD_FAILURE() << name << " accepted";
    } catch (const pf::InputError& e) {
      const std::string what = e.what();
      std::printf("  %s\n", what.c_str());
      EXPECT_NE(what.find("'" + name + "'"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  };
  auto with = [](const std::string& k, double x) { auto w = values(0.0, 0.5, false); w[k] = x; return w; };
  refusedNaming(with("Cohesion", -1.0), "Cohesion");
  refusedNaming(with("Friction Angle", 90.0), "Friction Angle");
  refusedNaming(with("Friction Angle", 120.0), "Friction Angle");
  refusedNaming(with("Friction Angle", -5.0), "Friction Angle");
  refusedNaming(with("Dilatancy Ratio", -0.1), "Dilatancy Ratio");
  refusedNaming(with("Dilatancy Ratio", 1.5), "Dilatancy Ratio");
  refusedNaming(with("Initial Hardening Parameter", 0.0), "Initial Hardening Parameter");
  refusedNaming(with("Initial Hardening Parameter", 1.2), "Initial Hardening Parameter");
  refusedNaming(with("Hardening Rate", -1.0), "Hardening Rate");
  refusedNaming(with("Plane Stress", 1.0), "Plane Stress");  // not a parameter of the correspondence models
  EXPECT_NO_THROW(pf::makeMaterial("Drucker Prager Correspondence", with("Dilatancy Ratio", 0.0)));
  EXPECT_NO_THROW(pf::makeMaterial("Drucker Prager Correspondence", with("Initial Hardening Parameter", 1.0)));
}
