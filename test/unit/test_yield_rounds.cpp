// Loading-balance correction (src/solvers/YieldRounds.hpp; Li & Geng, seed 003, Sec. 4.1):
//  1. the round logic: relax, admit, repeat until a relaxation admits nothing; the count of relaxations; the
//     cap of kMaxYieldRounds gives SolverFailure naming the step; a failing relaxation propagates;
//  2. the Drucker-Prager yield ratio the rounds test: 0 on the surface, J / J_yield - 1 off it; after a return
//     map it is round-off; the elastic trial of a yielding increment is past the tolerance;
//  3. Drucker Prager Correspondence honours FamilyView::admitted: a point held out takes the elastic trial (xi 0,
//     Hooke's stress) with Yield_Function past the tolerance; admitted, it returns to the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "materialpoint/MaterialPoint.hpp"
#include "materials/DruckerPragerPlasticity.hpp"
#include "solvers/Solver.hpp"
#include "solvers/YieldRounds.hpp"

namespace {

using pf::operator+;  // Mat3 is a std::array: argument lookup does not find pf's operators
using pf::operator*;

TEST(YieldRounds, RelaxesUntilNothingIsAdmitted) {
  const std::vector<double> admitted = {3, 1, 0};
  int relaxed = 0, asked = 0;
  const int rounds = pf::yieldRounds([&] { ++relaxed; }, [&] { return admitted[asked++]; }, 1.0);
  EXPECT_EQ(rounds, 3);
  EXPECT_EQ(relaxed, 3);
  EXPECT_EQ(asked, 3);
}

TEST(YieldRounds, ElasticStepTakesOneRelaxation) {
  int relaxed = 0;
  EXPECT_EQ(pf::yieldRounds([&] { ++relaxed; }, [] { return 0.0; }, 1.0), 1);
  EXPECT_EQ(relaxed, 1);
}

TEST(YieldRounds, CapFailsWithTheStepNamed) {
  int relaxed = 0;
  try {
    pf::yieldRounds([&] { ++relaxed; }, [] { return 2.0; }, 12.5);
    FAIL() << "no SolverFailure";
  } catch (const pf::SolverFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("t = 12.5"), std::string::npos) << what;
    EXPECT_NE(what.find("50 relaxations"), std::string::npos) << what;
  }
  EXPECT_EQ(relaxed, pf::kMaxYieldRounds);
}

TEST(YieldRounds, FailingRelaxationPropagates) {
  int asked = 0;
  EXPECT_THROW(pf::yieldRounds([] { throw pf::SolverFailure("no convergence"); }, [&] { return double(++asked); }, 1.0),
               pf::SolverFailure);
  EXPECT_EQ(asked, 0);
}

// Li & Geng's Table 2 constants (E 30 MPa, nu 0.25, phi 35 deg, c 60 kPa, m0 0.2, h 0, d0 0).
const pf::DruckerPragerLaw kLaw = pf::druckerPragerLaw(35.0, 60e3, 0.2, 0.0, 0.0);
const double kK = 30e6 / (3 * (1 - 2 * 0.25)), kG = 30e6 / (2 * (1 + 0.25));

TEST(YieldRounds, DruckerPragerRatioIsRelativeExcessOfJ) {
  // Hydrostatic compression p plus a shear tau_xy = q: I = 3 p, J = q, J_yield = m (3 A p + B).
  const double p = 500e3, m = kLaw.m0, jy = m * (3 * kLaw.A * p + kLaw.B);
  for (double q : {0.5 * jy, jy, 1.3 * jy}) {
    const pf::Mat3 tau = {-p, q, 0, q, -p, 0, 0, 0, -p};
    // Round-off of J and J_yield, each a few operations on values of order 1e5 Pa.
    EXPECT_NEAR(pf::druckerPragerYieldRatio(kLaw, tau, m), q / jy - 1.0, 1e-14) << q;
  }
}

TEST(YieldRounds, ReturnMapEndsOnTheSurfaceAndTrialIsPast) {
  // From a hydrostatic 500 kPa, a shear increment four times the elastic limit: the trial is far outside.
  const double p = 500e3, jy = kLaw.m0 * (3 * kLaw.A * p + kLaw.B), g = 4 * jy / (2 * kG);
  const pf::Mat3 tauN = {-p, 0, 0, 0, -p, 0, 0, 0, -p}, de = {0, g, 0, g, 0, 0, 0, 0, 0};
  const pf::DruckerPragerStep s = pf::druckerPragerUpdate(kLaw, kK, kG, tauN, 0.0, de);
  ASSERT_GT(s.dlambda, 0.0);
  // The return's dlambda tolerance is 1e-15 of J_trial / G: f after it is round-off of J_yield (1e-12 bound).
  EXPECT_LT(std::fabs(pf::druckerPragerYieldRatio(kLaw, s.tau, s.m)), 1e-12);
  const pf::Mat3 trial = tauN + (2 * kG) * de;  // de is deviatoric: the elastic trial
  EXPECT_NEAR(pf::druckerPragerYieldRatio(kLaw, trial, kLaw.m0), 3.0, 1e-12);
  EXPECT_GT(pf::druckerPragerYieldRatio(kLaw, trial, kLaw.m0), pf::kYieldTolerance);
}

TEST(YieldRounds, DruckerPragerHoldsAPointOutOfTheSetElastic) {
  auto mat = pf::makeMaterial("Drucker Prager Correspondence",
                              {{"Density", 2000.0}, {"Young's Modulus", 30e6}, {"Poisson's Ratio", 0.25},
                               {"Hourglass Coefficient", 0.0}, {"Friction Angle", 35.0}, {"Cohesion", 60e3},
                               {"Initial Hardening Parameter", 0.2}, {"Hardening Rate", 0.0}, {"Dilatancy Ratio", 0.0}});
  ASSERT_TRUE(mat->supportsYieldRounds());
  pf::MaterialPoint mp(*mat, 1e-3, 3.0);
  const double g = 0.005;  // pure shear: 2 G g = 120 kPa against the yield J = m0 B = 14 kPa at zero pressure
  const std::vector<char> out(mp.view().numNodes, 0), in(mp.view().numNodes, 1);
  mp.deform({1 + g, 0, 0, 0, 1 - g, 0, 0, 0, 1});
  mp.setAdmitted(out.data());
  mp.evaluate();
  EXPECT_EQ(mp.value("Equivalent_Plastic_Strain"), 0.0);
  // Hooke's law on the interior point's affine F (the lattice's K reproduces F to round-off): von Mises of the
  // small-strain shear 2 G g is sqrt(3) 2 G g; the strain increment from F differs from g by O(g^2) = 2.5e-5
  // relative (measured 7.3e-6), so the bound is 1e-4 relative; the returned state has 12 % of it.
  EXPECT_NEAR(mp.value("Von_Mises_Stress"), std::sqrt(3.0) * 2 * kG * g, 1e-4 * std::sqrt(3.0) * 2 * kG * g);
  EXPECT_GT(mp.value("Yield_Function"), 1.0);
  mp.setAdmitted(in.data());
  mp.evaluate();
  EXPECT_GT(mp.value("Equivalent_Plastic_Strain"), 0.0);
  EXPECT_LT(std::fabs(mp.value("Yield_Function")), 1e-12);  // the return's round-off, as above
  mp.setAdmitted(nullptr);  // no rounds: the normal update, the same state
  const double vm = mp.value("Von_Mises_Stress");
  mp.evaluate();
  EXPECT_EQ(mp.value("Von_Mises_Stress"), vm);
}

}  // namespace
