// Critical-stretch bond damage (core/BondDamage.hpp) in every model, on a two-point body (one bond each
// way, along x, |xi| = 1 mm):
//  1. a bond stretched past s_c breaks: no force, Damage 1; stretched back below s_c, or compressed, it
//     stays broken (never heals); a rolled-back step, or a later evaluation of the same step below s_c (a
//     quasi-static iterate), restores the unbroken bond (StateStore history, BondDamage.hpp's contract);
//  2. the energy a broken bond releases is the energy it stored at the break, against closed forms that
//     do not use the kernels: PMB pair energy c s^2 |xi| V^2 / 2 (Microelastic) and, for the OSB Elastic
//     model, 9 kappa s^2 V (a one-bond family has e^d = 0 and theta = 3 s, so W = kappa theta^2 / 2 per
//     node); the work of the computed pair force along the loading path is the same number.
// Units: SI; K = 100 GPa, G = 60 GPa, V = 1e-9 m^3 (3D), thickness 1 mm in 2D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/BondFamily.hpp"
#include "core/Material.hpp"
#include "core/StateStore.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

constexpr double kL = 1e-3, kV = 1e-9, kSc = 0.01;
// The damage fields of a view from the state, as Model wires them outside break rounds.
void attachDamage(pf::FamilyView& f, pf::StateStore& state) {
  f.brokenN = state.committed("Bond_Damage");
  f.broken = state.trial("Bond_Damage");
  f.damage = state.trial("Damage");
  f.brokenCountN = state.committed("Broken_Bonds");
  f.brokenCount = state.trial("Broken_Bonds");
  f.criticalStretch = kSc;
}

struct TwoPoints {
  std::vector<int> offsets = {0, 1, 2}, neighbors = {1, 0};
  std::vector<double> x = {0, 0, 0, kL, 0, 0}, V = {kV, kV}, m, ref = {kL, kL}, omega = {1, 1};
  pf::StateStore state;
  std::unique_ptr<pf::Material> mat;

  TwoPoints(const std::string& model, const std::map<std::string, double>& values) {
    mat = pf::makeMaterial(model, values);
    m.assign(2, kL * kL * kV);  // sum omega |xi|^2 V_j of the one bond
    std::vector<pf::StateSpec> specs = mat->stateSpecs();
    specs.push_back({"Bond_Damage", pf::Location::Bond, true, false});  // as Model declares them
    specs.push_back({"Broken_Bonds", pf::Location::Node, true, false});
    specs.push_back({"Damage", pf::Location::Node, false, true});
    state.allocate(specs, 2, 2);
    if (state.has("Stored_Elastic_Energy")) mat->enableOutput("Stored_Elastic_Energy");
  }
  pf::FamilyView view() {
    pf::FamilyView f;
    f.begin = 0; f.end = 2; f.offsets = offsets.data(); f.neighbors = neighbors.data(); f.refLength = ref.data();
    f.influence = omega.data(); f.unitInfluence = true; f.x = x.data(); f.volume = V.data();
    f.weightedVolume = m.data(); f.horizon = 1.5 * kL; f.numNodes = 2;
    attachDamage(f, state);
    return f;
  }
  // Force on node 1 (x component) with the bond at stretch s.
  double force(double s) {
    const std::vector<double> y = {0, 0, 0, kL * (1 + s), 0, 0};
    std::vector<double> F(6, 0.0);
    mat->computeForce(view(), y.data(), state, F.data());
    return F[3];
  }
  bool trialBroken() const {
    const double* b = const_cast<pf::StateStore&>(state).trial("Bond_Damage");
    return b[0] == 1.0 && b[1] == 1.0;
  }
  double damage(int i) { return state.trial("Damage")[i]; }
  double energy() {
    const double* e = state.trial("Stored_Elastic_Energy");
    return e[0] + e[1];
  }
};

std::map<std::string, double> solid(const std::string& dim) {
  std::map<std::string, double> v = {{"Density", 7800.0}, {"Bulk Modulus", 100e9}, {"Shear Modulus", 60e9}};
  if (dim != "3D") v[dim] = 1, v["Thickness"] = 1e-3;
  return v;
}

struct Case {
  std::string model, dim;
  std::map<std::string, double> values;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const std::string dim : {"3D", "Plane Stress", "Plane Strain"}) {
    out.push_back({"Elastic", dim, solid(dim)});
    std::map<std::string, double> ep = solid(dim);
    ep["Yield Stress"] = 1e12;  // stays elastic: the test is about breaking, not yielding
    out.push_back({"Elastic Plastic", dim, ep});
    ep["Isotropic Hardening Modulus"] = 1e9;
    ep["Apply Shear Correction Factor"] = 0;
    out.push_back({"Elastic Plastic Hardening", dim, ep});
    std::map<std::string, double> pmb = {{"Density", 7800.0}, {"Bulk Modulus", 100e9}};
    if (dim != "3D") pmb[dim] = 1, pmb["Thickness"] = 1e-3;
    out.push_back({"Microelastic", dim, pmb});
  }
  return out;
}

}  // namespace

// 1. Break, never heal, roll back. Forces are exactly zero once broken (the bond is out of every sum).
TEST(BondDamage, BreaksNeverHealsAndRollsBack) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.model + " " + c.dim);
    TwoPoints b(c.model, c.values);
    EXPECT_TRUE(b.mat->breaksBonds());  // else a block with a damage model is refused (ModelBuilder)
    EXPECT_LT(b.force(0.5 * kSc), 0.0);  // tension pulls node 1 (at +x) back
    EXPECT_FALSE(b.trialBroken());
    EXPECT_EQ(b.damage(0), 0.0);
    b.state.commit();
    EXPECT_EQ(b.force(1.5 * kSc), 0.0);  // past s_c: broken, no force
    EXPECT_TRUE(b.trialBroken());
    EXPECT_EQ(b.damage(0), 1.0);
    EXPECT_EQ(b.damage(1), 1.0);
    // A later evaluation of the same step (a quasi-static iterate) below s_c: the trial break is forgotten.
    EXPECT_NE(b.force(0.5 * kSc), 0.0);
    EXPECT_FALSE(b.trialBroken());
    EXPECT_EQ(b.damage(0), 0.0);
    EXPECT_EQ(b.force(1.5 * kSc), 0.0);
    EXPECT_TRUE(b.trialBroken());
    // A failed step is rolled back: the break was trial only, the bond is whole again.
    b.state.rollback();
    EXPECT_NE(b.force(0.5 * kSc), 0.0);
    EXPECT_FALSE(b.trialBroken());
    // The same break, committed: it never heals, below s_c or in compression.
    EXPECT_EQ(b.force(1.5 * kSc), 0.0);
    b.state.commit();
    for (double s : {0.5 * kSc, 0.0, -2.0 * kSc}) {
      EXPECT_EQ(b.force(s), 0.0) << s;
      EXPECT_TRUE(b.trialBroken()) << s;
      b.state.commit();
    }
  }
}

// Just below s_c the bond holds, at s_c it holds (the rule is s > s_c), just above it breaks.
TEST(BondDamage, ThresholdIsStrict) {
  TwoPoints b("Microelastic", {{"Density", 7800.0}, {"Bulk Modulus", 100e9}});
  b.force(kSc * (1 - 1e-9));
  EXPECT_FALSE(b.trialBroken());
  b.force(kSc * (1 + 1e-9));
  EXPECT_TRUE(b.trialBroken());
}

// 2. Energy released by a break = energy stored at the break, by closed forms; and = the work of the
// computed pair force from s = 0 to s_c (a linear force: the trapezoid rule is exact up to round-off, so
// 1e-12 relative). The closed forms are compared to 1e-12 too (round-off of a few products).
TEST(BondDamage, ReleasedEnergyIsStoredEnergyAtBreak) {
  const double K = 100e9;
  struct Model {
    std::string name;
    std::map<std::string, double> values;
    double closedForm;  // energy of the pair at s = s_c, times (1 - 1e-6)^2: the path ends just below s_c
  };
  // PMB 3D: c = 18 K / (pi delta^4); pair energy (both halves) c s^2 |xi| V^2 / 2.
  const double delta = 1.5 * kL, pi = 3.14159265358979323846;
  const double c = 18.0 * K / (pi * std::pow(delta, 4));
  const double s2 = kSc * kSc * (1 - 1e-6) * (1 - 1e-6);
  const std::vector<Model> models = {{"Microelastic", {{"Density", 7800.0}, {"Bulk Modulus", K}}, 0.5 * c * s2 * kL * kV * kV},
                                     {"Elastic", solid("3D"), 9.0 * K * s2 * kV}};
  for (const Model& md : models) {
    SCOPED_TRACE(md.name);
    TwoPoints b(md.name, md.values);
    const int steps = 200;
    const double sEnd = kSc * (1 - 1e-6);  // s_c itself could round to just above it and break
    double work = 0.0, fPrev = 0.0;
    for (int k = 1; k <= steps; ++k) {
      const double s = sEnd * k / steps;
      const double f = b.force(s);  // force density on node 1; force = f V, its work -f V dDelta
      work += -0.5 * (f + fPrev) * kV * kL * sEnd / steps;
      fPrev = f;
      b.state.commit();
    }
    const double stored = b.energy();
    EXPECT_FALSE(b.trialBroken());
    EXPECT_NEAR(stored, md.closedForm, 1e-12 * md.closedForm);
    EXPECT_NEAR(work, md.closedForm, 1e-12 * md.closedForm);
    // Past s_c: nothing is stored any more, so all of it was released; the force does no further work.
    EXPECT_EQ(b.force(1.01 * kSc), 0.0);
    EXPECT_EQ(b.energy(), 0.0);
  }
}

// The flag contract (core/BondDamage.hpp): the kernels skip the flags of intact nodes, yet after every
// evaluation the trial flags of every bond equal the rule applied from the committed flags, and committing
// or rolling back keeps both copies valid. A 5^3 lattice (every node's family), random growing motion, a
// random sequence of commits, rollbacks and repeated evaluations within a step; checked bond by bond.
TEST(BondDamage, FlagsFollowTheRuleThroughCommitsAndRollbacks) {
  pftest::Lattice L = pftest::makeLattice(5, false, 1e-3, 2.015, 0.0, pf::Influence::One, false);
  auto mat = pf::makeMaterial("Elastic", solid("3D"));
  pf::StateStore state;
  std::vector<pf::StateSpec> specs = mat->stateSpecs();
  specs.push_back({"Bond_Damage", pf::Location::Bond, true, false});
  specs.push_back({"Broken_Bonds", pf::Location::Node, true, false});
  specs.push_back({"Damage", pf::Location::Node, false, true});
  state.allocate(specs, L.numNodes, L.fam.numBonds());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pick(0.0, 1.0);
  std::vector<double> F(3 * L.numNodes), y(3 * L.numNodes);
  int breaksSeen = 0;
  for (int it = 0; it < 60; ++it) {
    const double amp = 2e-5 * it;  // up to 1.2e-3 of dx 1e-3: stretches up to about 2 %, s_c = 1 %
    for (int k = 0; k < 3 * L.numNodes; ++k) y[k] = L.x[k] + amp * u(rng);
    pf::FamilyView f = L.view();
    attachDamage(f, state);
    std::fill(F.begin(), F.end(), 0.0);
    mat->computeForce(f, y.data(), state, F.data());
    for (int i = 0; i < L.numNodes; ++i) {
      int count = 0;
      for (int b = L.fam.offsets[i]; b < L.fam.offsets[i + 1]; ++b) {
        const int j = L.fam.neighbors[b];
        const double d[3] = {y[3 * j] - y[3 * i], y[3 * j + 1] - y[3 * i + 1], y[3 * j + 2] - y[3 * i + 2]};
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const bool expect = f.brokenN[b] != 0.0 || len - L.fam.refLength[b] > kSc * L.fam.refLength[b];
        ASSERT_EQ(f.broken[b], expect ? 1.0 : 0.0) << "iteration " << it << " node " << i << " bond " << b;
        count += expect;
      }
      ASSERT_EQ(f.brokenCount[i], count);
      ASSERT_EQ(f.damage[i], static_cast<double>(count) / (L.fam.offsets[i + 1] - L.fam.offsets[i]));
      breaksSeen += count;
    }
    const double r = pick(rng);
    if (r < 0.5) state.commit();
    else if (r < 0.75) state.rollback();
    // else: another evaluation of the same step
  }
  EXPECT_GT(breaksSeen, 0);  // the sequence did break bonds
}
