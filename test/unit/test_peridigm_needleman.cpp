// Unit tests of Peridigm's Needleman update (materials/PeridigmJ2Update: peridigmNeedleman) on a material point in
// uniaxial strain at a constant rate (y stretched, x and z held; nu = 0: K = E/3, G = E/2), against closed forms:
//   - rate-dependent, no strain hardening (n = 0, e1 -> infinity): steady flow at the stress Y (eps_p' / r0)^m, with
//     eps_p' = 2 eps'/3 the equivalent plastic strain rate of incompressible flow in uniaxial strain;
//   - rate-independent power hardening (m = 0): sigma_vm = Y (1 + eps_p/e0)^n along the path.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/PeridigmJ2Update.hpp"

namespace {

using pf::Mat3;
constexpr double kE = 211e9, kY = 460e6, kK = kE / 3, kG = kE / 2;

struct Point {
  Mat3 tau{};
  double eqps = 0.0;
  double vm() const {
    const Mat3 s = pf::deviator(tau);
    return std::sqrt(1.5 * pf::ddot(s, s));
  }
};

// N steps of dt, each a uniaxial strain increment rate * dt.
Point uniaxialStrain(const pf::NeedlemanLaw& law, double rate, double dt, int N) {
  Point p;
  const Mat3 de = {0, 0, 0, 0, rate * dt, 0, 0, 0, 0};
  for (int k = 0; k < N; ++k) {
    const pf::PeridigmJ2Step s = pf::peridigmNeedleman(p.tau, de, p.eqps, kK, kG, kY, law, dt);
    p.tau = s.tau, p.eqps = s.eqps;
  }
  return p;
}

}  // namespace

// Below Y the point is elastic: sigma_yy = E eps (nu = 0), no plastic strain.
TEST(PeridigmNeedleman, ElasticBelowTheYieldStress) {
  pf::NeedlemanLaw law;
  law.n = 0.1, law.m = 0.01, law.rate0 = 1e-3, law.e0 = 0.00218, law.e1 = 0.436;
  const Point p = uniaxialStrain(law, 100.0, 1e-7, 10);  // eps = 1e-4, sigma = 21 MPa < Y
  EXPECT_NEAR(p.tau[4] / (kE * 1e-4), 1.0, 1e-12);        // round-off of 10 additions
  EXPECT_EQ(p.eqps, 0.0);
}

// Steady flow: sigma_vm = Y (2 eps'/(3 r0))^m, for three rates two decades apart. The bisection stops within 1e-6
// (relative) of its root and the flow stress moves by m times that, 5e-8 (measured 5.2e-8): bound 1e-7.
TEST(PeridigmNeedleman, SteadyFlowStressIsTheRateLaw) {
  pf::NeedlemanLaw law;
  law.n = 0.0, law.m = 0.05, law.rate0 = 1e-3, law.e0 = 1.0, law.e1 = 1e30;
  for (double rate : {1.0, 100.0, 1e4}) {
    SCOPED_TRACE(rate);
    const double dt = 1e-4 / rate;  // a strain of 1e-4 per step, 0.04 in all; the flow stress needs < 5e-3
    const Point p = uniaxialStrain(law, rate, dt, 400);
    const double expected = kY * std::pow(2.0 * rate / (3.0 * law.rate0), law.m);
    EXPECT_NEAR(p.vm() / expected, 1.0, 1e-7);
  }
}

// Rate-independent power hardening (m = 0): the surface follows Y (1 + eps_p/e0)^n with the model's own eps_p. The
// surface is evaluated at eps_n + sqrt(2/3) dl while eps_p grows by Peridigm's generic increment (projected on the
// mean stress direction): they differ by a small part of each step's increment, a few 1e-8 of the flow stress at n =
// 0.1 after 5000 steps (measured 9e-9): bound 1e-7.
TEST(PeridigmNeedleman, RateIndependentPowerHardening) {
  pf::NeedlemanLaw law;
  law.n = 0.1, law.m = 0.0, law.rate0 = 1.0, law.e0 = 0.00218, law.e1 = 1e30;
  const Point p = uniaxialStrain(law, 1.0, 1e-5, 5000);  // eps = 0.05
  ASSERT_GT(p.eqps, 0.02);
  EXPECT_NEAR(p.vm() / (kY * std::pow(1.0 + p.eqps / law.e0, law.n)), 1.0, 1e-7);
}

// A step of no length leaves the stress where it was (the rate term is infinite: no plastic flow), never NaN.
TEST(PeridigmNeedleman, StepOfNoLengthIsElastic) {
  pf::NeedlemanLaw law;
  law.n = 0.1, law.m = 0.01, law.rate0 = 1e-3, law.e0 = 0.00218, law.e1 = 0.436;
  const Point p = uniaxialStrain(law, 100.0, 1e-6, 100);
  const pf::PeridigmJ2Step s = pf::peridigmNeedleman(p.tau, Mat3{}, p.eqps, kK, kG, kY, law, 0.0);
  for (int a = 0; a < 9; ++a) EXPECT_EQ(s.tau[a], p.tau[a]);
  EXPECT_EQ(s.eqps, p.eqps);
}
