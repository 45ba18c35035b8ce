// Peridigm's velocity-Verlet bookkeeping (solvers/VerletPeridigm.hpp) against hand-computed values. The whole
// runs are checked against Peridigm's gold files (Compression_2x1x1, Body_Force__Explicit, ... in
// test/regression/peridigm.cmake).
#include <vector>

#include <gtest/gtest.h>

#include "solvers/VerletPeridigm.hpp"

// Compression_2x1x1's second step: the point at x = -1 has u_n = 1e-5 and v_{n+1/2} = 0.985 with dt = 1e-5.
// Peridigm's (x + u_n) + dt v rounds to -0.9999801500000001, x + (u_n + dt v) (what x + u_{n+1} gives) to
// -0.99998015, one ulp apart (values from Python's float arithmetic, IEEE double as here). The bond extension
// |y_1 - y_0| - 2 cancels five digits, so that ulp is a relative 5.6e-12 in the force: above Peridigm's
// tolerance 1e-9 N/m^3 on forces of 5e7.
TEST(VerletPeridigm, PositionsAreSummedInPeridigmsOrder) {
  const double x = -1.0, u = 1e-5, v = 0.985, dt = 1e-5;
  double y = 0.0;
  pf::peridigmPositions(&x, &u, &v, dt, 1, &y);
  EXPECT_EQ(y, -0.9999801500000001);
  const double uNext = u + dt * v;
  EXPECT_EQ(x + uNext, -0.99998015);
  EXPECT_NE(y, x + uNext);  // the two orders differ here: the test would notice a switch between them
}

// Only the prescribed components get dt/2 (f + b)/rho; a held one (v = 0 from its rate) then carries it.
TEST(VerletPeridigm, HalfKickReachesOnlyPrescribedComponents) {
  const std::vector<char> fixed = {1, 0, 0, 0, 0, 1};
  const std::vector<double> rho = {1000.0, 4000.0};
  const std::vector<double> f = {-2.0e5, 7.0, 7.0, 7.0, 7.0, 3.0e5};
  const std::vector<double> b = {0.0, 0.0, 0.0, 0.0, 0.0, 1.0e5};
  std::vector<double> v = {0.0, 1.5, 1.5, 1.5, 1.5, -2.0};
  pf::halfKickPrescribed(fixed, rho, f, b, 1e-3, v);
  EXPECT_DOUBLE_EQ(v[0], 0.5e-3 * -200.0);       // (f + b)/rho = -200 m/s^2
  EXPECT_DOUBLE_EQ(v[5], -2.0 + 0.5e-3 * 100.0);  // (3e5 + 1e5)/4000 = 100 m/s^2
  for (int k = 1; k < 5; ++k) EXPECT_EQ(v[k], 1.5);
}
