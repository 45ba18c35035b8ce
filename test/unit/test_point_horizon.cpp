// A horizon that varies by point (Peridigm's block Horizon as an expression in x, y, z; model/PointHorizons.hpp).
// Neighbour lists: each point's family holds the points within its own horizon (Peridigm's proximity search), checked
// against a brute-force double loop written here. Evaluation: the expression at each point, a non-positive value
// refused naming the block group and the point. Correspondence force: with families that are not symmetric, the
// two-phase evaluation (gather where every neighbour shares the point's horizon, one-pass elsewhere) against the
// one-pass scatter form of every point (Peridigm's summation), and the total force against zero (momentum balance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/Expression.hpp"
#include "core/InputError.hpp"
#include "discretization/NeighborSearch.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/CorrespondenceKinematics.hpp"
#include "test_input_helpers.hpp"
#include "model/PointHorizons.hpp"

namespace {

std::string sci(double v) {  // a measured value for the XML report (--gtest_output=xml)
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

// A 9 x 6 x 5 lattice of spacing 0.25 starting at the origin.
std::vector<double> lattice() {
  std::vector<double> x;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 9; ++i) x.insert(x.end(), {0.25 * i, 0.25 * j, 0.25 * k});
  return x;
}

TEST(PointHorizon, NeighbourListsMatchBruteForce) {
  const std::vector<double> x = lattice();
  const int n = static_cast<int>(x.size() / 3);
  // Horizons from 0.3001 (first and second lattice neighbours) at x = 0 to 0.7001 at x = 2: far from every
  // lattice distance sqrt(k)/4, so the search's tie tolerance (1e-13 of h^2) plays no part.
  std::vector<double> h(n);
  for (int p = 0; p < n; ++p) h[p] = 0.3001 + 0.2 * x[3 * p];
  pf::BondFamily fam;
  pf::buildFamilies(x, n, h, fam);
  ASSERT_EQ(fam.numOwned(), n);
  int asymmetric = 0;
  std::vector<std::set<int>> rows(n);
  for (int i = 0; i < n; ++i) rows[i].insert(fam.neighbors.begin() + fam.offsets[i], fam.neighbors.begin() + fam.offsets[i + 1]);
  for (int i = 0; i < n; ++i) {
    std::set<int> expected;
    for (int j = 0; j < n; ++j) {
      const double d0 = x[3 * j] - x[3 * i], d1 = x[3 * j + 1] - x[3 * i + 1], d2 = x[3 * j + 2] - x[3 * i + 2];
      if (j != i && d0 * d0 + d1 * d1 + d2 * d2 <= h[i] * h[i]) expected.insert(j);
    }
    EXPECT_EQ(rows[i], expected) << "point " << i;
    for (int j : expected) asymmetric += rows[j].count(i) == 0;
  }
  // The families are not symmetric: a point with the larger horizon holds bonds its neighbour does not.
  EXPECT_GT(asymmetric, 0);
  // Counts at the two ends: the corner (0, 0, 0) (h = 0.3001) has its 3 axis neighbours (a face diagonal is 0.354);
  // the corner (2, 0, 0) (h = 0.7001) every offset 0.25 (-a, b, c) with a^2 + b^2 + c^2 <= 16 h^2 (a <= 2, as 0.75 > h).
  EXPECT_EQ(fam.offsets[1] - fam.offsets[0], 3);
  int far = 0;
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 5; ++b)
      for (int c = 0; c <= 4; ++c) far += (a || b || c) && (a * a + b * b + c * c) / 16.0 <= 0.7001 * 0.7001;
  EXPECT_EQ(fam.offsets[9] - fam.offsets[8], far);  // point 8: (2, 0, 0)
}

TEST(PointHorizon, ExpressionAtEachPointAndRefusals) {
  pf::PointCloud c;
  c.x = {0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 1.0, 0.0, 2.0};
  c.volume = {1.0, 1.0, 1.0};
  c.block = {1, 2, 2};
  std::map<int, pf::HorizonRule> rules;
  rules[1] = {0.25, nullptr, "deck.xml: Blocks/A"};
  rules[2] = {0.0, std::make_shared<const pf::Expression>("0.5 + 0.25*x - 0.1*y + z*z", "deck.xml: Blocks/B/Horizon"),
              "deck.xml: Blocks/B"};
  const std::vector<double> h = pf::pointHorizons(c, rules);
  ASSERT_EQ(h.size(), 3u);
  EXPECT_EQ(h[0], 0.25);
  EXPECT_NEAR(h[1], 0.5 + 0.125 - 0.1, 1e-15);  // RTC's double arithmetic: a few ulps of 0.5
  EXPECT_NEAR(h[2], 0.5 + 0.25 + 4.0, 1e-15 * 5);
  // 0.75 - x: zero at the point (0.75, ...): refused with the group, the expression and the coordinates.
  c.x[3] = 0.75;
  rules[2].expression = std::make_shared<const pf::Expression>("0.75 - x", "deck.xml: Blocks/B/Horizon");
  const std::string msg = pftest::inputErrorOf([&] { pf::pointHorizons(c, rules); });
  EXPECT_NE(msg.find("deck.xml: Blocks/B: 'Horizon' = '0.75 - x' is 0 at the point (0.75, 1, 0) of block_2"),
            std::string::npos)
      << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  rules[2].expression = std::make_shared<const pf::Expression>("sqrt(x - 2)", "deck.xml: Blocks/B/Horizon");
  const std::string nan = pftest::inputErrorOf([&] { pf::pointHorizons(c, rules); });
  EXPECT_NE(nan.find("'Horizon' = 'sqrt(x - 2)' is nan at the point"), std::string::npos) << nan;
}

std::unique_ptr<pf::Material> elasticCorrespondence() {
  return pf::makeMaterial("Elastic Correspondence", {{"Density", 7800.0},
                                                     {"Young's Modulus", 200e9},
                                                     {"Poisson's Ratio", 0.3},
                                                     {"Hourglass Coefficient", 0.05}});
}

// The force of the lattice L (its families rebuilt from the per-point horizons h), nodes [0, split) through the
// two-phase evaluation (computeForce with rows, then completeForce), [split, n) one-pass.
std::vector<double> force(const pf::Material& mat, const pftest::Lattice& L, const std::vector<double>& h,
                          const std::vector<double>& y, int split, bool pointHorizons = true, int* gathered = nullptr) {
  std::vector<double> f(L.x.size(), 0.0), rows(static_cast<std::size_t>(pf::kGatherRow) * L.numNodes, 0.0);
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  pf::FamilyView twoPhase = L.view(0, split), onePass = L.view(split, L.numQueries);
  if (pointHorizons) twoPhase.pointHorizon = onePass.pointHorizon = h.data();
  twoPhase.exchange = rows.data(), twoPhase.exchangeStride = pf::kGatherRow;
  if (split > 0) mat.computeForce(twoPhase, y.data(), st, f.data());
  if (split < L.numQueries) mat.computeForce(onePass, y.data(), st, f.data());
  if (split > 0) mat.completeForce(twoPhase, y.data(), st, f.data());
  if (gathered) {
    *gathered = 0;
    for (int i = 0; i < split; ++i) *gathered += rows[static_cast<std::size_t>(pf::kGatherRow) * i + pf::kRowFlag] != 0.0;
  }
  return f;
}

TEST(PointHorizon, CorrespondenceTwoPhaseEqualsOnePassWithUnequalHorizons) {
  const auto mat = elasticCorrespondence();
  ASSERT_TRUE(mat->takesPointHorizon());
  pftest::Lattice L = pftest::makeLattice(9, false, 1e-3, 2.2, 0.0, pf::Influence(pf::Influence::ParabolicDecay), false);
  // Two regions of horizons 2.2 dx (x < 0) and 3.3 dx (x >= 0): interior points of each gather, points near the
  // interface (a neighbour of the other horizon) go one-pass. Families and omega from each point's own horizon.
  std::vector<double> h(L.numNodes);
  for (int p = 0; p < L.numNodes; ++p) h[p] = (L.x[3 * p] < -1e-9 ? 2.2 : 3.3) * L.dx;
  pf::buildFamilies(L.x, L.numQueries, h, L.fam);
  L.fam.influence.resize(L.fam.numBonds());
  for (int i = 0; i < L.numQueries; ++i)
    for (int b = L.fam.offsets[i]; b < L.fam.offsets[i + 1]; ++b)
      L.fam.influence[b] = pf::influenceValue(pf::Influence(pf::Influence::ParabolicDecay), L.fam.refLength[b], h[i]);
  L.fam.unitInfluence = false;
  const std::vector<double> y = pftest::jitteredMotion(L);
  const std::vector<double> ref = force(*mat, L, h, y, 0);  // every point one-pass: Peridigm's summation
  double scale = 0.0, total[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < ref.size(); ++k) scale = std::max(scale, std::fabs(ref[k])), total[k % 3] += ref[k];
  ASSERT_GT(scale, 0.0);
  // Momentum: equal volumes, so the forces sum to zero; round-off of ~1e5 bond terms, each up to ~10x the largest
  // net force, is ~1e-10 of it (measured 4e-14): bound 1e-9.
  for (double t : total) EXPECT_LT(std::fabs(t), 1e-9 * scale);
  RecordProperty("relative_total_force", sci(std::max({std::fabs(total[0]), std::fabs(total[1]), std::fabs(total[2])}) / scale));
  // The same sums in another order: agreement to round-off, 1e-12 relative (as test_correspondence_gather.cpp).
  for (int split : {L.numQueries, L.numQueries / 2}) {
    int gathered = 0;
    const std::vector<double> f = force(*mat, L, h, y, split, true, &gathered);
    // Both kinds of point take part: those with a neighbour of the other horizon (within 3.3 dx of x = 0) go one-pass.
    EXPECT_GT(gathered, 0);
    EXPECT_LT(gathered, split);
    double err = 0.0;
    for (std::size_t k = 0; k < f.size(); ++k) err = std::max(err, std::fabs(f[k] - ref[k]));
    EXPECT_LT(err, 1e-12 * scale) << "split " << split;
    RecordProperty("relative_error_split_" + std::to_string(split), sci(err / scale));
  }
  // Without the per-point horizons every point gathers as if its families were symmetric: the bonds only one end
  // holds are counted twice or not at all, an error of the order of the force itself. The check above can fail.
  const std::vector<double> wrong = force(*mat, L, h, y, L.numQueries, false);
  double err = 0.0;
  for (std::size_t k = 0; k < wrong.size(); ++k) err = std::max(err, std::fabs(wrong[k] - ref[k]));
  EXPECT_GT(err, 1e-3 * scale);
  RecordProperty("relative_error_without_point_horizons", sci(err / scale));
}

}  // namespace
