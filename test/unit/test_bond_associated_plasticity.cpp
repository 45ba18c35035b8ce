// The plastic bond-associated correspondence models (materials/BondAssociatedCorrespondenceMaterial.cpp with the
// laws of materials/BondStressLaw.cpp) against J2 closed forms written here, on a generated 9x9x9 lattice (horizon
// 2 dx, every family built), driven by an affine stretch without rotation F(t) = diag(1 + a t, 1 - b t, 1 - b t):
// every bond then has F_b = F(t) (the bond map is exact for affine motion) and R_b = I, and each step's unrotated
// strain increment is Peridigm's first-order L dt = I - F_n F_n+1^-1, diagonal. So every bond carries the
// one-point J2 history of that increment sequence:
//  1. Elastic Plastic: the radial return onto sqrt(3/2)|s| = Y (elastic until it yields), step by step;
//  2. Viscoplastic (Foster et al. 2010 Eqs. 49-61): the flow stress Y (1 + eps_p,n/eps0)^(1/n) (1 + rate/rate0)^(1/m)
//     with the rate implicit, solved here by bisection on the plastic strain increment;
//  3. Drucker-Prager (Li & Geng Eq. 38, perfectly plastic h = 0, m0 = 1, no dilatancy d0 = 0) on the compressive
//     stretch F(t) = diag(1 - a t, 1 + b t, 1 + b t): the return keeps I = -tr(tau) and scales the deviator onto
//     J = A I + B, xi += (J_tr - J) / (2 G) (Eqs. A10, A13);
//  4. each model's node output Equivalent_Plastic_Strain equals its bonds' (same law, same increments).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/StateStore.hpp"
#include "core/Tensor3.hpp"
#include "materials/CorrespondenceFields.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

constexpr double kE = 70e9, kNu = 0.3, kY = 300e6;
constexpr double kG = kE / (2 * (1 + kNu)), kK = kE / (3 * (1 - 2 * kNu));
// Foster's constants (the Taylor decks' kind of values, not their exact ones): n, m, eps0, rate0 [1/s].
constexpr double kN = 4.0, kM = 20.0, kEps0 = 0.01, kRate0 = 1e-3;
// Drucker-Prager: friction angle [degrees] and cohesion [Pa] (yields at the second step of the compressive stretch).
constexpr double kPhi = 30.0, kCohesion = 40e6;

std::unique_ptr<pf::Material> model(const std::string& name) {
  std::map<std::string, double> v = {{"Density", 2700.0}, {"Young's Modulus", kE}, {"Poisson's Ratio", kNu},
                                     {"Gradient Order Of Accuracy", 1.0}, {"Yield Stress", kY}};
  if (name.find("Drucker Prager") == 0) {
    v.erase("Yield Stress");
    v["Friction Angle"] = kPhi, v["Cohesion"] = kCohesion, v["Initial Hardening Parameter"] = 1.0;
    v["Hardening Rate"] = 0.0, v["Dilatancy Ratio"] = 0.0;
  }
  if (name.find("Viscoplastic") == 0) {
    v["Strain Hardening Exponent"] = kN, v["Rate Sensitivity Exponent"] = kM;
    v["Reference Plastic Strain"] = kEps0, v["Reference Plastic Strain Rate"] = kRate0;
  }
  return pf::makeMaterial(name, v, {});
}

// The stretch of step k (t = k s): axial 1 + a t, lateral 1 - b t (sign -1: axial 1 - a t, lateral 1 + b t).
constexpr double kA = 2.5e-3, kB = 0.4e-3;
double stretch(int axis, int k, double sign) { return axis == 0 ? 1.0 + sign * kA * k : 1.0 - sign * kB * k; }

// The one-point radial return of a diagonal stress (the three principal values) with the diagonal increment de and
// a plastic strain increment chosen by `flow` (given sigma_vm,tr and the mean stress, returns the new von Mises
// stress and d eps_p); the mean stress is kept.
struct Point {
  double tau[3] = {0, 0, 0};
  double eps = 0.0;
};

template <class Flow>
void radialReturn(Point& p, const double de[3], Flow flow) {
  const double tr = de[0] + de[1] + de[2];
  double trial[3];
  for (int a = 0; a < 3; ++a) trial[a] = p.tau[a] + kK * tr + 2 * kG * (de[a] - tr / 3);
  const double mean = (trial[0] + trial[1] + trial[2]) / 3;
  double s2 = 0.0;
  for (int a = 0; a < 3; ++a) s2 += (trial[a] - mean) * (trial[a] - mean);
  const double vmTrial = std::sqrt(1.5 * s2);
  double deps = 0.0;
  const double vm = flow(vmTrial, mean, deps);
  for (int a = 0; a < 3; ++a) p.tau[a] = mean + (trial[a] - mean) * (vm / vmTrial);
  p.eps += deps;
}

// Runs `steps` steps of the stretch on the lattice and compares every bond's unrotated stress (and plastic strain
// when eps_tol > 0) with the point history `expected` after each step.
template <class Expected>
void checkAgainstPoint(const std::string& name, int steps, Expected expected, double epsTol, double sign = 1.0) {
  auto mat = model(name);
  pftest::Lattice L = pftest::makeLattice(9, false, 1e-3, 2.0, 0.0, pf::Influence(pf::Influence::One), false);
  pf::StateStore st;
  st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
  std::vector<double> yN = L.x, y(L.x.size()), f(L.x.size());
  Point point;
  int plasticSteps = 0;
  for (int k = 1; k <= steps; ++k) {
    for (int p = 0; p < L.numNodes; ++p)
      for (int a = 0; a < 3; ++a) y[3 * p + a] = stretch(a, k, sign) * L.x[3 * p + a];
    double de[3];
    for (int a = 0; a < 3; ++a) de[a] = 1.0 - stretch(a, k - 1, sign) / stretch(a, k, sign);
    const double epsBefore = point.eps;
    expected(point, de);
    plasticSteps += point.eps > epsBefore ? 1 : 0;
    std::fill(f.begin(), f.end(), 0.0);
    pf::FamilyView v = L.view();
    v.time = k, v.startTime = 0.0, v.unitInfluence = true, v.yN = yN.data();
    mat->computeForce(v, y.data(), st, f.data());
    double worstTau = 0.0, worstEps = 0.0;
    const double* bondEps = st.trial("Bond_Equivalent_Plastic_Strain");
    const double* nodeEps = st.trial("Equivalent_Plastic_Strain");
    for (int b = 0; b < L.fam.numBonds(); ++b) {
      for (int c = 0; c < 6; ++c) {
        const double want = c < 3 ? point.tau[c] : 0.0;
        worstTau = std::max(worstTau, std::fabs(st.trial(std::string("Bond_Unrotated_Cauchy_Stress") + pf::kSym[c])[b] - want));
      }
      worstEps = std::max(worstEps, std::fabs(bondEps[b] - point.eps));
    }
    for (int i = 0; i < L.numQueries; ++i) worstEps = std::max(worstEps, std::fabs(nodeEps[i] - point.eps));
    // F_b and the increments to round-off (1e-15 relative) through Hooke's law: 1e-9 of Y is far above that and far
    // below a step's stress change (~1e-2 Y at least).
    EXPECT_LT(worstTau, 1e-9 * kY) << name << " step " << k;
    if (epsTol > 0) EXPECT_LT(worstEps, epsTol) << name << " step " << k << " eps_p " << point.eps;
    st.commit();
    yN = y;
  }
  EXPECT_GE(plasticSteps, 3) << "the stretch must yield the point for the test to mean anything";
}

TEST(BondAssociatedPlasticity, EveryBondFollowsThePerfectlyPlasticRadialReturn) {
  // Stress only: Peridigm's eps_p increment projects on the mean of two directions (PeridigmJ2Update.hpp), which is
  // the classical (sigma_tr - Y) / (3G) only once the state is on the surface; the stress is the closed form always.
  checkAgainstPoint("Elastic Plastic Bond Associated Correspondence", 6,
                    [](Point& p, const double de[3]) {
                      radialReturn(p, de, [](double vmTrial, double, double& deps) {
                        deps = vmTrial > kY ? (vmTrial - kY) / (3 * kG) : 0.0;
                        return std::min(vmTrial, kY);
                      });
                    },
                    0.0);
}

TEST(BondAssociatedPlasticity, EveryBondFollowsFostersViscoplasticUpdate) {
  // Each step is 1 s long (time k). Eq. 60 for the plastic strain increment x: vm_tr - 3G x = Y h (1 + x/rate0)^(1/m)
  // with h = (1 + eps_n/eps0)^(1/n) (hardening at the step's start); its left side falls and right side rises in x.
  checkAgainstPoint("Viscoplastic Bond Associated Correspondence", 6,
                    [](Point& p, const double de[3]) {
                      const double epsN = p.eps;
                      radialReturn(p, de, [epsN](double vmTrial, double, double& deps) {
                        const double h = kY * std::pow(1 + epsN / kEps0, 1 / kN);
                        auto g = [&](double x) { return vmTrial - 3 * kG * x - h * std::pow(1 + x / kRate0, 1 / kM); };
                        deps = 0.0;
                        if (g(0.0) <= 0.0) return vmTrial;
                        double lo = 0.0, hi = vmTrial / (3 * kG);
                        for (int it = 0; it < 200; ++it) {
                          const double mid = 0.5 * (lo + hi);
                          (g(mid) > 0 ? lo : hi) = mid;
                        }
                        deps = 0.5 * (lo + hi);
                        return vmTrial - 3 * kG * deps;
                      });
                    },
                    1e-12);
}

TEST(BondAssociatedPlasticity, EveryBondFollowsTheDruckerPragerConeReturn) {
  const double pi = 3.14159265358979323846, sinPhi = std::sin(kPhi * pi / 180), cosPhi = std::cos(kPhi * pi / 180);
  const double A = 2 * sinPhi / (std::sqrt(3.0) * (3 - sinPhi)), B = 6 * kCohesion * cosPhi / (std::sqrt(3.0) * (3 - sinPhi));
  checkAgainstPoint("Drucker Prager Bond Associated Correspondence", 6,
                    [A, B](Point& p, const double de[3]) {
                      radialReturn(p, de, [A, B](double vmTrial, double mean, double& deps) {
                        const double jTrial = vmTrial / std::sqrt(3.0), jYield = A * (-3 * mean) + B;
                        deps = jTrial > jYield ? (jTrial - jYield) / (2 * kG) : 0.0;
                        return std::sqrt(3.0) * std::min(jTrial, jYield);
                      });
                    },
                    1e-12, -1.0);
}

}  // namespace
