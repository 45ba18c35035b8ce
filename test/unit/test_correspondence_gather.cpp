// The correspondence force in gather form (Material::exchangeWidth / completeForce: each node sums its own
// force from its neighbours' rows A = P K^-1, F, c) against the one-pass scatter form it replaces
// (f_i += T_i V_j, f_j -= T_i V_i), on a whole lattice under a non-affine motion with hourglass forces:
// the two are the same sums in another order, so they agree to round-off. Also a body split into a gather
// block and a scatter block (a one-pass model beside a two-phase one: zero rows, reactions added directly).
// The reference is the scatter form, an independent summation of the same force states; the force states
// themselves are checked against closed forms in test_correspondence.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "LatticeFixture.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/CorrespondenceKinematics.hpp"

namespace {

using pf::Dimension;

std::unique_ptr<pf::Material> elastic(Dimension dim) {
  std::map<std::string, double> v = {{"Density", 7800.0}, {"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3},
                                     {"Hourglass Coefficient", 0.05}};
  if (dim == Dimension::PlaneStrain) v["Plane Strain"] = 1, v["Thickness"] = 1e-3;
  return pf::makeMaterial("Elastic Correspondence", v);
}

double maxAbs(const std::vector<double>& v) {
  double m = 0;
  for (double a : v) m = std::max(m, std::fabs(a));
  return m;
}

// Force of the lattice with nodes [0, split) in gather form and [split, n) in scatter form.
std::vector<double> force(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& y, int split) {
  std::vector<double> f(L.x.size(), 0.0), rows(static_cast<std::size_t>(pf::kGatherRow) * L.numNodes, 0.0);
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  pf::FamilyView gather = L.view(0, split), scatter = L.view(split, L.numQueries);
  gather.exchange = rows.data(), gather.exchangeStride = pf::kGatherRow;
  if (split > 0) mat.computeForce(gather, y.data(), st, f.data());
  if (split < L.numQueries) mat.computeForce(scatter, y.data(), st, f.data());
  if (split > 0) mat.completeForce(gather, y.data(), st, f.data());
  return f;
}

TEST(CorrespondenceGather, EqualsScatterFormToRoundOff) {
  for (bool planar : {false, true}) {
    SCOPED_TRACE(planar ? "plane strain" : "3D");
    auto mat = elastic(planar ? Dimension::PlaneStrain : Dimension::ThreeD);
    const pftest::Lattice L =
        pftest::makeLattice(planar ? 13 : 7, planar, 1e-3, 3.0, 1e-3, pf::Influence(pf::Influence::One), false);
    ASSERT_EQ(mat->exchangeWidth(L.view()), pf::kGatherRow);
    const std::vector<double> y = pftest::jitteredMotion(L);
    const std::vector<double> ref = force(*mat, L, y, 0);
    const double scale = maxAbs(ref);
    ASSERT_GT(scale, 0.0);
    // Round-off of sums of ~10^2 terms of either sign, each up to ~10x the largest net force: 1e-12 relative
    // (a wrong sign or a missing reaction shows at order 1).
    for (int split : {L.numQueries, L.numQueries / 2}) {
      const std::vector<double> f = force(*mat, L, y, split);
      double err = 0;
      for (std::size_t k = 0; k < f.size(); ++k) err = std::max(err, std::fabs(f[k] - ref[k]));
      EXPECT_LT(err, 1e-12 * scale) << "split " << split;
    }
  }
}

}  // namespace
