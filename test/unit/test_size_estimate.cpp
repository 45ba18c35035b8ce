// The size estimate against built clouds: points exact for grids (an upper bound with holes), the interior
// family equal to the largest family buildFamilies finds, bonds an upper bound within a stated factor, and the
// guard's one-line refusals -- reached in milliseconds for decks whose cloud would not fit anywhere.
#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "core/InputError.hpp"
#include "discretization/Discretization.hpp"
#include "discretization/NeighborSearch.hpp"
#include "discretization/SizeEstimate.hpp"

namespace {

using Type = pf::DiscretizationSpec::Type;

pf::Deck deckWith(const pf::DiscretizationSpec& d, double horizon) {
  pf::Deck deck;
  deck.file = "deck.xml";
  deck.discretization = d;
  pf::BlockGroupSpec b;
  b.horizon = horizon;
  deck.blocks.push_back(b);
  return deck;
}

pf::DiscretizationSpec generatorSpec(Type type, double dx, std::array<double, 3> length) {
  pf::DiscretizationSpec d;
  d.type = type;
  d.spacing = dx;
  d.length = length;
  d.thickness = dx;
  return d;
}

// The independent count: the families of the built cloud.
struct Counted {
  double points = 0, bonds = 0, largestFamily = 0;
};

Counted count(const pf::Deck& deck) {
  const pf::PointCloud c = pf::buildDiscretization(deck.discretization, deck.file);
  pf::BondFamily fam;
  pf::buildFamilies(c.x, c.size(), std::vector<double>(c.size(), deck.maxHorizon()), fam,
                    c.partialVolume ? &c.cell : nullptr);
  Counted n;
  n.points = c.size();
  n.bonds = static_cast<double>(fam.numBonds());
  for (int i = 0; i < c.size(); ++i) n.largestFamily = std::max(n.largestFamily, double(fam.offsets[i + 1] - fam.offsets[i]));
  return n;
}

// Exact points and interior family; bonds an upper bound, at most `factor` times the true count (small clouds
// are mostly surface, where families are cut).
void expectMatches(const pf::Deck& deck, double factor) {
  const pf::SizeEstimate e = pf::estimateSize(deck);
  const Counted n = count(deck);
  EXPECT_EQ(e.points, n.points);
  EXPECT_EQ(e.family, n.largestFamily);
  EXPECT_GE(e.bonds, n.bonds);
  EXPECT_LE(e.bonds, factor * n.bonds);
}

}  // namespace

TEST(SizeEstimate, LatticeCountsInBalls) {
  // Lattice points within radius 3 (plus ties): 123 in 3D, 29 in 2D, less the centre.
  EXPECT_EQ(pf::latticeFamily({1, 1, 1}, {100, 100, 100}, 3.015, false), 122.0);
  EXPECT_EQ(pf::latticeFamily({1, 1, 0}, {100, 100, 1}, 3.015, false), 28.0);
  EXPECT_EQ(pf::latticeFamily({1, 1, 1}, {100, 100, 100}, 3.0, false), 122.0);  // ties count, as in the search
  // A grid two points wide bounds the offsets to +-1 along that axis (an upper bound: one point has only one).
  EXPECT_EQ(pf::latticeFamily({1, 1, 1}, {2, 1, 1}, 3.015, false), 2.0);
  // Large radii switch to the continuum volume: within 0.1 % of the ball.
  const double r = 3000.0, ball = 3.14159265358979 * r * r;
  EXPECT_NEAR(pf::latticeFamily({1, 1, 0}, {1e5, 1e5, 1}, r, false) / ball, 1.0, 1e-3);
}

TEST(SizeEstimate, BoxWithLayersExact) {
  pf::DiscretizationSpec d = generatorSpec(Type::BoxWithHoles, 1.0, {14, 9, 8});
  d.layers = {"Left", "Right", "Front"};
  d.layerWidth = 3.015;
  expectMatches(deckWith(d, 3.015), 3.0);
}

TEST(SizeEstimate, RectanglePartialVolumeExact) {
  pf::DiscretizationSpec d = generatorSpec(Type::RectangleWithHoles, 0.5, {20, 12, 0});
  d.partialVolume = true;
  d.gridNodes = true;
  expectMatches(deckWith(d, 2.5), 2.0);
}

TEST(SizeEstimate, QuickGridUnequalCellsExact) {
  pf::DiscretizationSpec d;
  d.type = Type::QuickGrid;
  d.length = {2.0, 1.2, 0.8};
  d.count = {20, 10, 8};  // cells 0.1 x 0.12 x 0.1
  expectMatches(deckWith(d, 0.35), 3.0);
  d.partialVolume = true;
  expectMatches(deckWith(d, 0.35), 3.0);
}

TEST(SizeEstimate, HolesGiveAnUpperBound) {
  pf::DiscretizationSpec d = generatorSpec(Type::RectangleWithHoles, 0.1, {4, 2, 0});
  pf::HoleSpec h;
  h.centre = {2.0, 1.0, 0.0};
  h.radius = 0.5;
  d.holes = {h};
  const pf::Deck deck = deckWith(d, 0.3015);
  const pf::SizeEstimate e = pf::estimateSize(deck);
  const Counted n = count(deck);
  EXPECT_TRUE(e.holes);
  EXPECT_GE(e.points, n.points);
  EXPECT_LE(e.points, 1.12 * n.points);  // the hole is 9.8 % of the plate
  EXPECT_GE(e.bonds, n.bonds);
  EXPECT_EQ(e.family, n.largestFamily);
}

TEST(SizeEstimate, MeshFileFromMeanSpacing) {
  const std::string path = ::testing::TempDir() + "size_estimate_mesh.txt";
  {
    std::ofstream f(path);
    f << "# x y z block volume\n";
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 10; ++i) f << i * 0.2 << " " << j * 0.2 << " " << k * 0.2 << " 1 0.008\n";
  }
  pf::DiscretizationSpec d;
  d.type = Type::TextFile;
  d.meshFile = path;
  const pf::Deck deck = deckWith(d, 0.603);
  const pf::SizeEstimate e = pf::estimateSize(deck);
  const Counted n = count(deck);
  EXPECT_TRUE(e.meshFile);
  EXPECT_EQ(e.points, n.points);
  EXPECT_EQ(e.family, n.largestFamily);
  EXPECT_GE(e.bonds, n.bonds);
}

// The cases: each refused in well under a second, with one line naming what to change.
TEST(SizeEstimate, HugeDecksRefusedAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  pf::DiscretizationSpec fine = generatorSpec(Type::RectangleWithHoles, 1e-7, {0.1, 0.1, 0});
  const pf::Deck spacing = deckWith(fine, 3e-7);
  pf::DiscretizationSpec grid;
  grid.type = Type::QuickGrid;
  grid.length = {0.1, 0.1, 0.001};
  grid.count = {100000, 100000, 1};
  const pf::Deck points = deckWith(grid, 3e-6);
  const pf::Deck horizon = deckWith(generatorSpec(Type::BoxWithHoles, 0.0005, {0.1, 0.02, 0.02}), 1.0);
  for (const pf::Deck* deck : {&spacing, &points, &horizon}) {
    const pf::SizeEstimate e = pf::estimateSize(*deck);
    try {
      pf::checkSize(*deck, e, 1, 24e9, "the memory available");
      ADD_FAILURE() << "not refused: " << e.points << " points, " << e.bonds << " bonds";
    } catch (const pf::InputError& err) {
      const std::string msg = err.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_NE(msg.find("deck.xml"), std::string::npos) << msg;
      EXPECT_NE(msg.find("'Horizon'"), std::string::npos) << msg;
    }
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(SizeEstimate, LimitNamedInTheRefusal) {
  const pf::Deck deck = deckWith(generatorSpec(Type::BoxWithHoles, 0.002, {0.1, 0.02, 0.02}), 0.00603);
  const pf::SizeEstimate e = pf::estimateSize(deck);
  EXPECT_NO_THROW(pf::checkSize(deck, e, 2, 24e9, "'Maximum Memory'"));
  const std::string msg = [&] {
    try {
      pf::checkSize(deck, e, 2, 1e6, "'Maximum Memory'");
    } catch (const pf::InputError& err) {
      return std::string(err.what());
    }
    return std::string("<no error>");
  }();
  EXPECT_NE(msg.find("'Maximum Memory' (1 MB)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'Spacing'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("np 2"), std::string::npos) << msg;
}
