// Partial-volume quadrature (src/PartialVolume.hpp): the share of a grid cell inside a ball, checked
// against closed forms (the cells of a lattice tile the ball exactly) and a brute-force midpoint sum.
#include <gtest/gtest.h>

#include <cmath>

#include "core/BondFamily.hpp"
#include "discretization/NeighborSearch.hpp"
#include "discretization/Discretization.hpp"
#include "discretization/PartialVolume.hpp"
#include "test_input_helpers.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// Midpoint-rule share of the cell at d inside the ball, n samples per axis (independent of the
// closed-form/Gauss code under test).
double bruteForce(const std::array<double, 3>& d, const std::array<double, 3>& cell, double R, int n) {
  long inside = 0, total = 0;
  const int nz = cell[2] > 0 ? n : 1;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < nz; ++c) {
        const double x = d[0] + cell[0] * ((a + 0.5) / n - 0.5), y = d[1] + cell[1] * ((b + 0.5) / n - 0.5);
        const double z = cell[2] > 0 ? d[2] + cell[2] * ((c + 0.5) / nz - 0.5) : d[2];
        inside += x * x + y * y + z * z <= R * R;
        ++total;
      }
  return double(inside) / total;
}

}  // namespace

// Every lattice cell's share summed over the lattice is the ball's measure: pi R^2 (2D, closed form) and
// 4/3 pi R^3 (3D, Gauss-Legendre between the kinks of the section area); measured within 7e-16 in both,
// bound 1e-12 (round-off of ~10^3 terms). Radii include lattice ties (3, 5: cell centres on the sphere).
TEST(PartialVolume, LatticeCellsTileTheBall) {
  for (double R : {1.0, 3.0, 3.015, 5.0, 7.3}) {
    const int n = static_cast<int>(R) + 2;
    double a2 = 0.0, a3 = 0.0;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j) {
        a2 += pf::cellFractionInBall({double(i), double(j), 0.0}, {1.0, 1.0, 0.0}, R);
        for (int k = -n; k <= n; ++k) a3 += pf::cellFractionInBall({double(i), double(j), double(k)}, {1.0, 1.0, 1.0}, R);
      }
    EXPECT_NEAR(a2 / (kPi * R * R), 1.0, 1e-12) << "R = " << R;
    EXPECT_NEAR(a3 / (4.0 / 3.0 * kPi * R * R * R), 1.0, 1e-12) << "R = " << R;
  }
}

// Single cells, including a non-cubic one, against the brute-force midpoint sum (its own error is
// ~1/n of the cell's boundary fraction: 400 per axis in 2D, 120 in 3D -> bounds 2e-3 / 1e-2 of the
// share).
TEST(PartialVolume, SingleCellsMatchBruteForce) {
  struct Case { std::array<double, 3> d, cell; double R; };
  const Case cases[] = {{{3.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, 3.2},   {{2.5, -2.0, 0.0}, {1.0, 0.5, 0.0}, 3.0},
                        {{0.0, 5.0, 0.0}, {1.0, 1.0, 0.0}, 5.0},   {{2.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, 2.6},
                        {{1.0, -2.0, 2.0}, {1.0, 1.0, 1.0}, 3.015}, {{0.5, 1.5, -2.0}, {1.0, 2.0, 0.5}, 2.4}};
  for (const Case& c : cases) {
    const double f = pf::cellFractionInBall(c.d, c.cell, c.R);
    const bool is3d = c.cell[2] > 0;
    const double ref = bruteForce(c.d, c.cell, c.R, is3d ? 120 : 400);
    EXPECT_GT(f, 0.0);
    EXPECT_LT(f, 1.0);
    EXPECT_NEAR(f, ref, is3d ? 1e-2 * ref : 2e-3 * ref) << c.d[0] << " " << c.d[1] << " " << c.d[2];
  }
  EXPECT_EQ(pf::cellFractionInBall({1.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, 3.0), 1.0);  // wholly inside
  EXPECT_EQ(pf::cellFractionInBall({4.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, 3.0), 0.0);  // wholly outside
}

// The point of partial volumes: a 2D lattice family at delta/dx = 5 has the shear moment
// sum x^2 nx^2 ny^2 V / m = 1/8 of the isotropic continuum within 0.5 % (whole volumes: +8.7 %).
TEST(PartialVolume, MakesTheLatticeFamilyNearlyIsotropic) {
  const double R = 5.0;
  std::vector<double> pts = {0.0, 0.0, 0.0};
  for (int i = -7; i <= 7; ++i)
    for (int j = -7; j <= 7; ++j)
      if (i || j) pts.insert(pts.end(), {double(i), double(j), 0.0});
  auto shearMoment = [&](const std::array<double, 3>* cell) {
    pf::BondFamily fam;
    pf::buildFamilies(pts, 1, {R}, fam, cell);
    double m = 0.0, s = 0.0;
    for (std::size_t b = 0; b < fam.numBonds(); ++b) {
      const int j = fam.neighbors[b];
      const double x = fam.refLength[b], w = fam.fraction.empty() ? 1.0 : fam.fraction[b];
      const double nx = pts[3 * j] / x, ny = pts[3 * j + 1] / x;
      m += w * x * x;
      s += w * x * x * nx * nx * ny * ny;
    }
    return s / m / 0.125 - 1.0;
  };
  const std::array<double, 3> cell = {1.0, 1.0, 0.0};
  EXPECT_GT(shearMoment(nullptr), 0.08);  // the lattice's anisotropy this test is about
  EXPECT_LT(std::fabs(shearMoment(&cell)), 0.005);
}

// Partial volumes need grid cells: a Text File discretization with it is an input error naming the
// parameter; a generated grid gets its cell.
TEST(PartialVolume, NeedsARegularGrid) {
  pftest::writeTemp("pf_pv_mesh.txt", "0 0 0 1 0.5\n1.0 0 0 1 0.5\n");
  Teuchos::ParameterList d;
  d.set("Type", std::string("Text File"));
  d.set("Input Mesh File", std::string("pf_pv_mesh.txt"));
  d.set("Partial Volume", true);
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, "deck.xml", ::testing::TempDir()), "deck.xml", "'Partial Volume'");
  Teuchos::ParameterList g;
  g.set("Type", std::string("Rectangle With Holes"));
  g.set("Spacing", 0.001);
  g.set("X Length", 0.01);
  g.set("Y Length", 0.005);
  g.set("Thickness", 0.001);
  g.set("Partial Volume", true);
  const pf::PointCloud c = pftest::cloudOf(g, "deck.xml", ".");
  EXPECT_TRUE(c.partialVolume);
  EXPECT_EQ(c.cell[0], 0.001);
  EXPECT_EQ(c.cell[1], 0.001);
  EXPECT_EQ(c.cell[2], 0.0);  // flat axis of a 2D grid
}
