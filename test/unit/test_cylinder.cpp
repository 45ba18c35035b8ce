// The Cylinder discretization (discretization/CylinderGenerator.hpp): counts against Foster et al. (2010),
// geometry of the lattice, input errors.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "test_input_helpers.hpp"

using Teuchos::ParameterList;

namespace {

ParameterList cylinderList(double radius, double length, double dx, const std::string& axis = "z") {
  ParameterList d;
  d.set("Type", std::string("Cylinder"));
  d.set("X Center", 1.0);
  d.set("Y Center", -2.0);
  d.set("Z Center", 0.5);
  d.set("Axis", axis);
  d.set("Radius", radius);
  d.set("Length", length);
  d.set("Spacing", dx);
  return d;
}

}  // namespace

TEST(Cylinder, FostersTaylorBarAtFortyAcrossHasThePapersPointCount) {
  // Foster, Silling & Chen (2010), section 10: L = 31.75 mm, D = 6.35 mm, 40 nodes across, 252 800 nodes.
  const double d0 = 6.35e-3;
  const pf::PointCloud c = pftest::cloudOf(cylinderList(d0 / 2, 31.75e-3, d0 / 40), "deck.xml", ".");
  EXPECT_EQ(c.size(), 252800);
}

TEST(Cylinder, LatticeFillsTheDiscAlongTheAxis) {
  // 8 across, 5 long along x: 52 centres of the 8 x 8 cell grid lie in the disc of radius 4 cells.
  const double dx = 0.25;
  const pf::PointCloud c = pftest::cloudOf(cylinderList(1.0, 1.25, dx, "x"), "deck.xml", ".");
  ASSERT_EQ(c.size(), 52 * 5);
  double lo = 1e300, hi = -1e300;
  for (int p = 0; p < c.size(); ++p) {
    const double* x = &c.x[3 * p];
    lo = std::min(lo, x[0]);
    hi = std::max(hi, x[0]);
    const double r2 = (x[1] + 2.0) * (x[1] + 2.0) + (x[2] - 0.5) * (x[2] - 0.5);
    EXPECT_LE(r2, 1.0 + 1e-12);
    EXPECT_EQ(c.volume[p], dx * dx * dx);
    // Every in-plane coordinate is a cell centre of the grid centred on the axis (exact: binary fractions).
    EXPECT_EQ(std::fmod(x[1] + 2.0 + 1.0, dx), 0.5 * dx);
  }
  EXPECT_EQ(lo, 1.0 + 0.5 * dx);  // first layer half a cell above the base face
  EXPECT_EQ(hi, 1.0 + 1.25 - 0.5 * dx);
  // The first layer comes first (impact-face points have the lowest ids).
  for (int p = 0; p < 52; ++p) EXPECT_EQ(c.x[3 * p], lo);
  EXPECT_EQ(c.cell[0], dx);
  EXPECT_EQ(c.spacing, dx);
}

TEST(Cylinder, LengthOrDiameterOffTheLatticeIsAnInputError) {
  EXPECT_INPUT_ERROR(pftest::cloudOf(cylinderList(1.0, 1.3, 0.25), "deck.xml", "."), "deck.xml", "'Length'");
  EXPECT_INPUT_ERROR(pftest::cloudOf(cylinderList(1.1, 1.25, 0.25), "deck.xml", "."), "deck.xml", "'Radius'");
}

TEST(Cylinder, AxisOtherThanALatticeDirectionIsAnInputError) {
  EXPECT_INPUT_ERROR(pftest::cloudOf(cylinderList(1.0, 1.25, 0.25, "1 1 0"), "deck.xml", "."), "deck.xml", "Axis");
}
