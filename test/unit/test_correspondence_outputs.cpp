// The correspondence models' optional tensor and vector outputs (materials/CorrespondenceOutputs.cpp), against
// closed forms and an independent sum:
//  1. Unrotated_Rate_Of_Deformation of a uniaxial stretch F_xx = 1 + r t in steps dt: the midpoint rate
//     r / (1 + r t_mid) of each step (Rate Of Deformation = Midpoint) or Peridigm's end-of-step r / (1 + r t) (no
//     rotation: d = D), the other components 0; an evaluation without time passing keeps the committed rate;
//  2. Cauchy_Stress = R tau R^T: after a uniaxial stretch along x, a rigid 30 degree turn Q about z in one step
//     gives sigma = Q tau Q^T;
//  3. Hourglass_Force_Density of a non-affine motion in gather form equals the force with the hourglass
//     coefficient less the force without it (the stress part does not depend on it), node by node.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "LatticeFixture.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "core/Tensor3.hpp"
#include "materials/CorrespondenceKinematics.hpp"

namespace {

constexpr double kDx = 1e-3;

std::unique_ptr<pf::Material> elastic(double hourglass, const std::string& rule = "End Of Step") {
  return pf::makeMaterial("Elastic Correspondence",
                          {{"Density", 7800.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3},
                           {"Hourglass Coefficient", hourglass}},
                          {{"Rate Of Deformation", rule}});
}

// The rate output of a uniaxial stretch F_xx = 1 + r t in three steps of dt against expected(t), then an evaluation
// without time passing (it keeps the committed rate).
void checkUniaxialRate(const std::string& rule, const std::function<double(double t, double dt)>& expected) {
  auto mat = elastic(0.0, rule);
  mat->enableOutput("Unrotated_Rate_Of_DeformationXX");
  pf::MaterialPoint mp(*mat, kDx, 3.0);
  const double r = 1e3, dt = 1e-5;  // strain rate 1/s, step s: 1 % per step
  for (int k = 1; k <= 3; ++k) {
    const double t = k * dt;
    mp.setTime(t);
    mp.deform({1 + r * t, 0, 0, 0, 1, 0, 0, 0, 1});
    mp.evaluate();
    // round-off of F (bond sums, ~1e-15) over the increment r dt = 1e-2, times r
    EXPECT_NEAR(mp.value("Unrotated_Rate_Of_DeformationXX"), expected(t, dt), 1e-10 * r) << "step " << k;
    for (const char* c : {"YY", "ZZ", "XY", "YZ", "XZ"})
      EXPECT_NEAR(mp.value(std::string("Unrotated_Rate_Of_Deformation") + c), 0.0, 1e-10 * r) << c;
    mp.commit();
  }
  const double committed = mp.state().committed("Unrotated_Rate_Of_DeformationXX")[0];
  mp.evaluate();  // the same time again: no step
  EXPECT_EQ(mp.value("Unrotated_Rate_Of_DeformationXX"), committed);
}

TEST(CorrespondenceOutputs, RateOfDeformationIsTheMidpointRate) {
  checkUniaxialRate("Midpoint", [](double t, double dt) { return 1e3 / (1 + 1e3 * (t - 0.5 * dt)); });
}

// Peridigm's rate (the default of Elastic Correspondence): Fdot F^-1 at the step's end, r / (1 + r t).
TEST(CorrespondenceOutputs, RateOfDeformationEndOfStepIsPeridigms) {
  checkUniaxialRate("End Of Step", [](double t, double) { return 1e3 / (1 + 1e3 * t); });
}

TEST(CorrespondenceOutputs, CauchyStressIsTheRotatedUnrotatedStress) {
  auto mat = elastic(0.0, "Midpoint");  // its rigid turn in one step is exact with the midpoint rule only
  mat->enableOutput("Cauchy_StressXX");
  pf::MaterialPoint mp(*mat, kDx, 3.0);
  mp.deform({1.001, 0, 0, 0, 1, 0, 0, 0, 1});
  mp.evaluate();
  const double tauXX = mp.value("Unrotated_Cauchy_StressXX"), tauYY = mp.value("Unrotated_Cauchy_StressYY");
  ASSERT_GT(tauXX, 1e8);  // E eps (1 - nu) / ((1 + nu)(1 - 2 nu)) = 2.7e8 Pa
  EXPECT_NEAR(mp.value("Cauchy_StressXX"), tauXX, 1e-9 * tauXX);  // no rotation yet: sigma = tau
  mp.commit();
  // A rigid 30 degree turn Q about z in one step: tau keeps its value (objectivity, test_correspondence.cpp) and
  // sigma = Q tau Q^T, whose xy = (tau_xx - tau_yy) sin 30 cos 30 tells Q from Q^T. Tolerance: Flanagan-Taylor's R
  // equals Q to round-off for a rigid increment (the Cayley map), 1e-9 of tau.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const pf::Mat3 Q = {c, -s, 0, s, c, 0, 0, 0, 1};
  mp.deform(pf::mul(Q, pf::Mat3{1.001, 0, 0, 0, 1, 0, 0, 0, 1}));
  mp.evaluate();
  EXPECT_NEAR(mp.value("Unrotated_Cauchy_StressXX"), tauXX, 1e-9 * tauXX);
  EXPECT_NEAR(mp.value("Cauchy_StressXX"), c * c * tauXX + s * s * tauYY, 1e-9 * tauXX);
  EXPECT_NEAR(mp.value("Cauchy_StressYY"), s * s * tauXX + c * c * tauYY, 1e-9 * tauXX);
  EXPECT_NEAR(mp.value("Cauchy_StressXY"), s * c * (tauXX - tauYY), 1e-9 * tauXX);
}

// The gather-form force of the whole lattice; hourglass: its Hourglass_Force_Density (3 per node) when asked.
std::vector<double> gatherForce(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y,
                                std::vector<double>* hourglass) {
  std::vector<double> f(L.x.size(), 0.0), rows(static_cast<std::size_t>(pf::kGatherRow) * L.numNodes, 0.0);
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  pf::FamilyView v = L.view();
  v.exchange = rows.data(), v.exchangeStride = pf::kGatherRow;
  mat.computeForce(v, y.data(), st, f.data());
  mat.completeForce(v, y.data(), st, f.data());
  if (hourglass) {
    hourglass->assign(L.x.size(), 0.0);
    for (int a = 0; a < 3; ++a) {
      const double* h = st.trial(std::string("Hourglass_Force_Density") + "XYZ"[a]);
      for (int p = 0; p < L.numQueries; ++p) (*hourglass)[3 * p + a] = h[p];
    }
  }
  return f;
}

TEST(CorrespondenceOutputs, HourglassForceDensityIsTheHourglassPartOfTheForce) {
  const pftest::Lattice L = pftest::makeLattice(7, false, kDx, 2.015, 0.0, pf::Influence::One, false);
  const std::vector<double> y = pftest::jitteredMotion(L);
  auto with = elastic(0.05), without = elastic(0.0);
  with->enableOutput("Hourglass_Force_DensityX");
  std::vector<double> hg;
  const std::vector<double> f = gatherForce(*with, L, y, &hg), f0 = gatherForce(*without, L, y, nullptr);
  double scale = 0.0, diff = 0.0, force = 0.0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    scale = std::max(scale, std::fabs(hg[k]));
    force = std::max(force, std::fabs(f[k]));
    diff = std::max(diff, std::fabs(hg[k] - (f[k] - f0[k])));
  }
  ASSERT_GT(scale, 1e-6 * force);  // the motion does excite the hourglass force
  EXPECT_LT(diff, 1e-12 * force);  // round-off of the stress part, which cancels in f - f0
}

// Peridigm's rate from the velocities (FamilyView::velocity, Verlet): Fdot = sum omega (v_j - v_i) (x) xi V_j K^-1
// equals A for an affine velocity v = A x (reference: A itself), at a corner point too; and with velocities the
// End Of Step model's rate output is sym(A F^-1) (here F = I at the step's end: sym(A)) even though the positions did
// not move (F - F_n = 0; unrotated by the step's R): the velocity drives it, as in Peridigm. Tolerance: round-off of the bond sums and K^-1.
TEST(CorrespondenceOutputs, EndOfStepRateIsTheVelocityGradient) {
  const pftest::Lattice L = pftest::makeLattice(5, false, kDx, 2.015, 0.0, pf::Influence::One, false);
  const pf::Mat3 A = {300.0, -50.0, 20.0, 10.0, -200.0, 40.0, -30.0, 60.0, 100.0};  // 1/s
  std::vector<double> v(L.x.size());
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < 3; ++a)
      v[3 * p + a] = A[3 * a] * L.x[3 * p] + A[3 * a + 1] * L.x[3 * p + 1] + A[3 * a + 2] * L.x[3 * p + 2];
  for (int i : {0, L.numNodes / 2}) {  // a corner, the centre
    const pf::ShapeAndGradient sg = pf::shapeAndGradient(L.view(), i, L.x.data(), false);
    const pf::Mat3 Fdot = pf::velocityGradient(L.view(), i, v.data(), sg.Kinv, false);
    for (int c = 0; c < 9; ++c) EXPECT_NEAR(Fdot[c], A[c], 1e-12 * 300.0) << "node " << i << " component " << c;
  }
  auto mat = elastic(0.0);
  mat->enableOutput("Unrotated_Rate_Of_DeformationXX");
  pf::StateStore st;
  st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
  pf::FamilyView view = L.view();
  view.velocity = v.data();
  view.time = 1e-6;  // one step of 1e-6 s from startTime 0
  std::vector<double> f(L.x.size(), 0.0);
  mat->computeForce(view, L.x.data(), st, f.data());
  // d = R^T sym(A) R with the step's rotation R (the spin of A turns it by |W| dt ~ 4e-5)
  pf::Mat3 R;
  const char* full[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
  for (int c = 0; c < 9; ++c) R[c] = st.trial(std::string("Rotation_Tensor") + full[c])[L.numNodes / 2];
  ASSERT_GT(std::fabs(R[1]) + std::fabs(R[2]) + std::fabs(R[5]), 1e-6);  // the spin did turn it
  const pf::Mat3 D = pf::mulTN(R, pf::mul(pf::sym(A), R));
  const char* names[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  const int at[6] = {0, 4, 8, 1, 5, 2};
  for (int c = 0; c < 6; ++c)
    EXPECT_NEAR(st.trial(std::string("Unrotated_Rate_Of_Deformation") + names[c])[L.numNodes / 2], D[at[c]], 1e-9)
        << names[c];
}

}  // namespace
