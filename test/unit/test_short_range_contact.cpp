// Peridigm's short-range contact law (core/ShortRangeContact.hpp) against its closed form: the normal force
// 9 k (r_c - d) / (pi h^5) V_j per end, Coulomb friction mu |F_n| against the relative tangential velocity, and
// Newton's third law between the two points' forces (force density times volume).
#include <cmath>

#include <gtest/gtest.h>

#include "core/ShortRangeContact.hpp"

namespace pf {
namespace {

const ShortRangeForceLaw kLaw{0.5, 2.0e3};

double endMagnitude(double h, double d, double volumeJ) {
  return 9.0 * kLaw.springConstant * (kLaw.contactRadius - d) / (M_PI * std::pow(h, 5)) * volumeJ;
}

TEST(ShortRangeContact, NoForceAtOrBeyondTheContactRadius) {
  const double yi[3] = {0, 0, 0}, yj[3] = {0.5, 0, 0}, v[3] = {0, 0, 0};
  double f[3] = {0, 0, 0};
  EXPECT_FALSE(addShortRangeForce(kLaw, 0.3, ContactPair{yi, yj, v, v, 1.0, 1.0, 1.0}, f));
  EXPECT_EQ(f[0], 0.0);
}

TEST(ShortRangeContact, NormalForcePushesApartWithBothEndsHorizons) {
  const double yi[3] = {0, 0, 0}, yj[3] = {0.12, 0.16, 0}, v[3] = {0, 0, 0};  // d = 0.2 along (0.6, 0.8, 0)
  double f[3] = {0, 0, 0};
  ASSERT_TRUE(addShortRangeForce(kLaw, 0.0, ContactPair{yi, yj, v, v, 0.7, 1.0, 1.5}, f));
  const double m = endMagnitude(1.0, 0.2, 0.7) + endMagnitude(1.5, 0.2, 0.7);
  // 1e-14 relative: the closed form and the law round differently in the last bits only.
  EXPECT_NEAR(f[0], -0.6 * m, 1e-14 * m);
  EXPECT_NEAR(f[1], -0.8 * m, 1e-14 * m);
  EXPECT_EQ(f[2], 0.0);
}

TEST(ShortRangeContact, FrictionOpposesTheRelativeTangentialVelocity) {
  // i slides along +y over j at rest, pressed along x; the normal parts of the velocities carry no friction.
  const double yi[3] = {0, 0, 0}, yj[3] = {0.3, 0, 0}, vi[3] = {5.0, 2.0, 0}, vj[3] = {-1.0, 0, 0};
  double f[3] = {0, 0, 0};
  const double mu = 0.25;
  ASSERT_TRUE(addShortRangeForce(kLaw, mu, ContactPair{yi, yj, vi, vj, 1.0, 1.0, 1.0}, f));
  const double m = 2.0 * endMagnitude(1.0, 0.3, 1.0);
  EXPECT_NEAR(f[0], -m, 1e-14 * m);
  EXPECT_NEAR(f[1], -mu * m, 1e-14 * m);
  EXPECT_NEAR(f[2], 0.0, 1e-14 * m);
}

TEST(ShortRangeContact, PairForcesBalance) {
  // Force density times volume: what i gets from j is minus what j gets from i, friction included.
  const double yi[3] = {0.1, -0.2, 0.05}, yj[3] = {0.25, -0.1, -0.1}, vi[3] = {1, 2, 3}, vj[3] = {-2, 0.5, 1};
  const double Vi = 0.8, Vj = 1.3, hi = 1.0, hj = 1.2;
  double fi[3] = {0, 0, 0}, fj[3] = {0, 0, 0};
  ASSERT_TRUE(addShortRangeForce(kLaw, 0.4, ContactPair{yi, yj, vi, vj, Vj, hi, hj}, fi));
  ASSERT_TRUE(addShortRangeForce(kLaw, 0.4, ContactPair{yj, yi, vj, vi, Vi, hj, hi}, fj));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fi[c] * Vi, -fj[c] * Vj, 1e-12 * std::fabs(fi[0] * Vi));
}

TEST(ShortRangeContact, StoredEnergyIsThePotentialOfTheNormalForce) {
  // Both halves of the pair's energy, U(d), against the normal force on i: F = -dU/dd along the pair, by a central
  // difference (step 1e-6 of r_c: the quadratic U makes the difference exact up to round-off, 1e-8 relative).
  const double Vi = 0.8, Vj = 1.3, hi = 1.0, hj = 1.2, v[3] = {0, 0, 0};
  auto energy = [&](double d) {
    const double yi[3] = {0, 0, 0}, yj[3] = {d, 0, 0};
    return shortRangeHalfEnergy(kLaw, ContactPair{yi, yj, v, v, Vj, hi, hj}, Vi) +
           shortRangeHalfEnergy(kLaw, ContactPair{yj, yi, v, v, Vi, hj, hi}, Vj);
  };
  const double d = 0.3, h = 1e-6 * kLaw.contactRadius;
  const double yi[3] = {0, 0, 0}, yj[3] = {d, 0, 0};
  double f[3] = {0, 0, 0};
  ASSERT_TRUE(addShortRangeForce(kLaw, 0.0, ContactPair{yi, yj, v, v, Vj, hi, hj}, f));
  const double force = -f[0] * Vi;  // the spring pushes i to -x, away from j: K (r_c - d) > 0
  EXPECT_NEAR(-(energy(d + h) - energy(d - h)) / (2 * h), force, 1e-8 * force);
  EXPECT_EQ(energy(kLaw.contactRadius), 0.0);
}

}  // namespace
}  // namespace pf
