// Thermal expansion in "Elastic Plastic" (the J2 thermal kernel, osbJ2ThermalForce) and "Microelastic"
// (docs/thermal.md), on small lattices (5 points a side, delta = 2 dx, 3D, plane stress, plane strain):
//  1. with Temperature_Change 0 everywhere the thermal path gives the mechanics-only kernel's bits (force, and
//     every trial state the J2 model writes), after a plastic step;
//  2. a uniform heating of a free body, y = (1 + a dT) x, is force-free with no plastic flow (3D, plane stress);
//  3. Microelastic and Elastic with a non-uniform dT: the pair forces stay odd (sum f V = 0) and the exact tangent
//     is the derivative of the force (central differences), the thermal stretch included;
//  4. critical stretch on the mechanical stretch: a bond heated by a dT = 2 s_c and stretched freely does not
//     break, stretched s_c / 2 beyond that it stays, 3 s_c / 2 beyond it breaks (J2 and Microelastic).
// The closed forms of free and clamped blocks are the regression tests (test/regression/thermal.cmake).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/FieldValues.hpp"
#include "core/StateStore.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

using pf::Dimension;
constexpr double kDx = 1e-3, kH = 1e-3, kAlpha = 1e-5;
const Dimension kDims[3] = {Dimension::ThreeD, Dimension::PlaneStress, Dimension::PlaneStrain};

std::map<std::string, double> values(const std::string& model, Dimension dim, double alpha) {
  std::map<std::string, double> v = {{"Density", 7800.0}};
  if (model == "Microelastic") {
    v["Bulk Modulus"] = 100e9;
  } else {
    v["Young's Modulus"] = 200e9;
    v["Poisson's Ratio"] = 0.3;
    if (model != "Elastic") v["Yield Stress"] = 100e6;
  }
  if (alpha != 0.0) v["Thermal Expansion Coefficient"] = alpha;
  if (dim == Dimension::PlaneStress) v["Plane Stress"] = 1;
  if (dim == Dimension::PlaneStrain) v["Plane Strain"] = 1;
  if (dim != Dimension::ThreeD) v["Thickness"] = kH;
  return v;
}

// One evaluation of a whole lattice (every family built), with Temperature_Change dT and, if sc > 0, bond damage.
struct Evaluation {
  pf::StateStore state;
  std::vector<double> force;
  pf::FieldValues fields;

  Evaluation(const pftest::Lattice& L, const pf::Material& mat, const std::vector<double>& y,
             const std::vector<double>& dT, double sc = 0.0) {
    std::vector<pf::StateSpec> specs = mat.stateSpecs();
    if (sc > 0.0) {  // as Model declares them
      specs.push_back({"Bond_Damage", pf::Location::Bond, true, false});
      specs.push_back({"Broken_Bonds", pf::Location::Node, true, false});
      specs.push_back({"Damage", pf::Location::Node, false, true});
    }
    state.allocate(specs, L.numQueries, L.fam.numBonds());
    force.assign(3 * L.numNodes, 0.0);
    fields.entries = {{"Temperature_Change", dT.data()}};
    pf::FamilyView v = L.view();
    v.fields = &fields;
    if (sc > 0.0) {
      v.brokenN = state.committed("Bond_Damage");
      v.broken = state.trial("Bond_Damage");
      v.damage = state.trial("Damage");
      v.brokenCountN = state.committed("Broken_Bonds");
      v.brokenCount = state.trial("Broken_Bonds");
      v.criticalStretch = sc;
    }
    mat.computeForce(v, y.data(), state, force.data());
  }
};

pftest::Lattice lattice(Dimension dim) {
  pftest::Lattice L = pftest::makeLattice(5, dim != Dimension::ThreeD, kDx, 2.0, kH, pf::Influence::One, false);
  L.fam.unitInfluence = true;
  return L;
}

}  // namespace

// 1. The thermal path at dT = 0 is the mechanics-only kernel to the bit, yielding points included (a random motion
//    of 2 % of dx strains the lattice far past sigma_y = 100 MPa).
TEST(ThermalExpansion, J2AtZeroTemperatureChangeIsTheMechanicsKernel) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(pf::toString(dim));
    const pftest::Lattice L = lattice(dim);
    auto hot = pf::makeMaterial("Elastic Plastic", values("Elastic Plastic", dim, kAlpha));
    auto cold = pf::makeMaterial("Elastic Plastic", values("Elastic Plastic", dim, 0.0));
    ASSERT_EQ(hot->fieldsRead(), std::vector<std::string>{"Temperature_Change"});
    ASSERT_TRUE(cold->fieldsRead().empty());
    EXPECT_FALSE(hot->hasForceDerivative());  // the implicit solvers differentiate numerically
    const std::vector<double> y = randomMotion(L, 2e-2 * kDx, 11), dT(L.numNodes, 0.0);
    Evaluation a(L, *hot, y, dT), b(L, *cold, y, dT);
    for (std::size_t k = 0; k < a.force.size(); ++k) ASSERT_EQ(a.force[k], b.force[k]) << "force " << k;
    double plastic = 0.0;
    for (const char* name : {"Dilatation", "Lambda", "Equivalent_Plastic_Strain", "Von_Mises_Stress"})
      for (int i = 0; i < L.numQueries; ++i) ASSERT_EQ(a.state.trial(name)[i], b.state.trial(name)[i]) << name << " " << i;
    for (int i = 0; i < L.numQueries; ++i) plastic = std::max(plastic, a.state.trial("Equivalent_Plastic_Strain")[i]);
    EXPECT_GT(plastic, 0.0);  // the comparison covered the return mapping
    const double* ep = a.state.trial("Deviatoric_Plastic_Extension");
    for (std::size_t b2 = 0; b2 < L.fam.numBonds(); ++b2)
      ASSERT_EQ(ep[b2], b.state.trial("Deviatoric_Plastic_Extension")[b2]) << "bond " << b2;
  }
}

// 2. Free uniform heating: every bond's mechanical extension is 0 (to round-off), so no force and no plastic flow,
//    though a dT = 1e-2 is 20 times the yield strain. Tolerance: relative to the largest force of the same body
//    held (y = x), 1e-10 (round-off of |Y| - (1 + a dT)|xi|: 1e-16 / 1e-2 per bond).
TEST(ThermalExpansion, FreeUniformHeatingIsForceFree) {
  for (const char* model : {"Elastic Plastic", "Microelastic"})
    for (Dimension dim : {Dimension::ThreeD, Dimension::PlaneStress}) {
      SCOPED_TRACE(std::string(model) + " " + pf::toString(dim));
      const pftest::Lattice L = lattice(dim);
      auto mat = pf::makeMaterial(model, values(model, dim, kAlpha));
      const double dT0 = 1000.0, s = kAlpha * dT0;
      std::vector<double> y = L.x, dT(L.numNodes, dT0);
      for (double& v : y) v *= 1.0 + s;
      Evaluation e(L, *mat, y, dT), held(L, *mat, L.x, dT);
      double fmax = 0.0, scale = 0.0;
      for (double f : e.force) fmax = std::max(fmax, std::fabs(f));
      for (double f : held.force) scale = std::max(scale, std::fabs(f));
      ASSERT_GT(scale, 0.0);
      EXPECT_LT(fmax, 1e-10 * scale) << "max |f| " << fmax << " held " << scale;
      if (e.state.has("Equivalent_Plastic_Strain")) {
        for (int i = 0; i < L.numQueries; ++i) ASSERT_EQ(e.state.trial("Equivalent_Plastic_Strain")[i], 0.0) << i;
      }
    }
}

namespace {
// The material's exact tangent at y (Evaluation e, Temperature_Change dT) along a random direction against central
// differences of its force, h = 1e-6 of the direction: within 1e-7 of max |dF| (truncation and round-off both far
// below; a missing term of the thermal stretch shows at the force's own scale).
void expectTangentIsTheDerivative(const pftest::Lattice& L, const pf::Material& mat, const std::vector<double>& y,
                                  const Evaluation& e, const std::vector<double>& dT) {
  std::vector<double> dy = randomMotion(L, kDx, 5);
  for (std::size_t k = 0; k < dy.size(); ++k) dy[k] -= L.x[k];
  std::vector<double> dF(y.size(), 0.0);
  pf::FamilyView v = L.view();
  v.fields = &e.fields;
  ASSERT_TRUE(mat.forceDerivative(v, y.data(), dy.data(), e.state, dF.data()));
  const double h = 1e-6;
  std::vector<double> yp = y, ym = y;
  for (std::size_t k = 0; k < y.size(); ++k) { yp[k] += h * dy[k]; ym[k] -= h * dy[k]; }
  Evaluation ep(L, mat, yp, dT), em(L, mat, ym, dT);
  double maxd = 0, maxerr = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    maxd = std::max(maxd, std::fabs(dF[k]));
    maxerr = std::max(maxerr, std::fabs((ep.force[k] - em.force[k]) / (2 * h) - dF[k]));
  }
  ASSERT_GT(maxd, 0.0);
  EXPECT_LT(maxerr, 1e-7 * maxd);
}
}  // namespace

// 3. Microelastic and Elastic, dT varying from point to point (0 to 200 K). Microelastic: node i's half of a bond
//    loses a dT_i, so the pair force sees the mean of its ends'; Elastic: node i's bonds lose a dT_i |xi| in its own
//    force state. Both stay odd pair by pair: sum f V = 0 to round-off (1e-12 of sum |f| V). Their exact tangents
//    (the thermal stretch shifts T, theta and t, not their derivatives) against central differences, as
//    Microelastic.ForceDerivativeMatchesCentralDifferences (1e-7 of max |dF|); Elastic's without the shift misses
//    by 2.5 % of max |dF| (mutation thermal-tangent).
TEST(ThermalExpansion, NonUniformHeating) {
  for (const char* model : {"Microelastic", "Elastic"})
    for (Dimension dim : kDims) {
      SCOPED_TRACE(std::string(model) + " " + pf::toString(dim));
      const pftest::Lattice L = lattice(dim);
      auto mat = pf::makeMaterial(model, values(model, dim, kAlpha));
      ASSERT_TRUE(mat->hasForceDerivative());
      std::vector<double> dT(L.numNodes);
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> u(0.0, 200.0);
      for (double& v : dT) v = u(rng);
      const std::vector<double> y = randomMotion(L, 1e-3 * kDx, 3);
      Evaluation e(L, *mat, y, dT);
      double sum[3] = {0, 0, 0}, scale = 0.0;
      for (int p = 0; p < L.numNodes; ++p)
        for (int a = 0; a < 3; ++a) {
          sum[a] += e.force[3 * p + a] * L.volume[p];
          scale += std::fabs(e.force[3 * p + a]) * L.volume[p];
        }
      for (int a = 0; a < 3; ++a) EXPECT_LE(std::fabs(sum[a]), 1e-12 * scale) << "component " << a;
      expectTangentIsTheDerivative(L, *mat, y, e, dT);
    }
}

// 4. Critical stretch s_c on the mechanical stretch: a lattice heated by a dT = 2 s_c and stretched uniformly by
//    f (y = (1 + f) x) breaks no bond for f = a dT + 3 s_c / 4 and every bond for f = a dT + 5 s_c / 4 (a = alpha; in
//    plane strain (1 + nu) alpha, the free in-plane stretch, in both models), though f > s_c in both. (With alpha in
//    plane strain the first would break: nu alpha dT + 3 s_c / 4 > s_c.)
TEST(ThermalExpansion, BondsBreakOnTheMechanicalStretch) {
  for (const char* model : {"Elastic Plastic", "Microelastic"})
    for (Dimension dim : kDims) {
      SCOPED_TRACE(std::string(model) + " " + pf::toString(dim));
      const pftest::Lattice L = lattice(dim);
      auto mat = pf::makeMaterial(model, values(model, dim, kAlpha));
      const double nu = std::string(model) == "Microelastic" ? 0.25 : 0.3;
      const double a = dim == Dimension::PlaneStrain ? (1 + nu) * kAlpha : kAlpha, sc = 1e-3, dT0 = 2 * sc / a;
      const std::vector<double> dT(L.numNodes, dT0);
      for (double beyond : {0.75, 1.25}) {
        std::vector<double> y = L.x;
        for (double& v : y) v *= 1.0 + a * dT0 + beyond * sc;
        Evaluation e(L, *mat, y, dT, sc);
        double broken = 0.0;
        for (int i = 0; i < L.numQueries; ++i) broken += e.state.trial("Broken_Bonds")[i];
        EXPECT_EQ(broken, beyond < 1.0 ? 0.0 : static_cast<double>(L.fam.numBonds())) << "beyond " << beyond;
      }
    }
}
