// The hidden-mode test of Elastic Bond Associated Correspondence (materials/ElasticBondAssociatedCorrespondence-
// Material.cpp, Chen & Spencer 2019): its linearised force on a 3D slab with a lattice hole (the staircase of the
// band tests, three layers, bottom row clamped) has no eigenvalue with a non-negative real part: no zero-energy and
// no growing mode, without any hourglass term. The bond-associated model has no surface band (it never reads
// FamilyView::band: its bond gradients answer the zero-energy modes, not the surface effect), so "band on" does
// not apply; it is tested as built. Reuses the band tests' harness (LinearisedForce.hpp). Units: SI, dx = 1 mm.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "LatticeFixture.hpp"
#include "LinearisedForce.hpp"
#include "core/StateStore.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

constexpr double kDx = 1e-3;

// 11 x 11 x 3 points minus a hole of radius 2.5 dx (21 points a layer), delta = 2.015 dx (up to 32 bonds).
pftest::Lattice slabWithHole() { return pftest::latticeWithHole(11, 2.5 * kDx, kDx, 2.015, 3); }

std::unique_ptr<pf::Material> material(const std::string& name, double hourglass) {
  std::map<std::string, double> v = {{"Density", 2000.0}, {"Young's Modulus", 30e6}, {"Poisson's Ratio", 0.25}};
  if (hourglass >= 0) v["Hourglass Coefficient"] = hourglass;
  return pf::makeMaterial(name, v, {});
}

// One evaluation from the reference (start time 0, t = 1, nothing committed: the step's increment is y - x), each
// with fresh state; the two-phase models run both phases (an exchange row per node where the model has one).
std::vector<double> force(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y) {
  pf::FamilyView v = L.view();
  v.time = 1.0, v.startTime = 0.0;
  v.unitInfluence = true;
  const int w = mat.exchangeWidth(v);
  std::vector<double> rows(static_cast<std::size_t>(w) * L.numNodes, 0.0), f(L.x.size(), 0.0);
  if (w > 0) v.exchange = rows.data(), v.exchangeStride = w;
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  mat.computeForce(v, y.data(), st, f.data());
  if (w > 0) mat.completeForce(v, y.data(), st, f.data());
  return f;
}

double largestRealPart(const std::string& name, double hourglass) {
  const pftest::Lattice L = slabWithHole();
  const std::unique_ptr<pf::Material> mat = material(name, hourglass);
  return pftest::largestRealPart(L, [&](const std::vector<double>& y) { return force(*mat, L, y); }, true);
}

// Measured largest Re / |lambda|max: -1.31e-4, the slab's lowest elastic mode (Elastic Correspondence on the same
// slab: -1.14e-4 without hourglass, -1.24e-4 at 0.05, printed for comparison: on this small clamped slab with
// delta = 2.015 dx its hidden modes do not reach zero either, so the comparison shows no difference). Bound: -1e-5,
// a hundred times the difference quotients' error (~1e-7 of |lambda|max), a tenth of the lowest mode's.
TEST(BondAssociatedStability, NoZeroEnergyOrGrowingModeAroundALatticeHole) {
  const double ba = largestRealPart("Elastic Bond Associated Correspondence", -1);
  const double ec0 = largestRealPart("Elastic Correspondence", 0.0);
  std::printf("largest Re / |lambda|max: bond-associated %.3g; Elastic Correspondence at Hourglass 0 %.3g\n", ba, ec0);
  EXPECT_LT(ba, -1e-5);
}

}  // namespace
