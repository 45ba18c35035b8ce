// Duplicate points (issue 15 part 3): found within the tolerance also across cell faces, the smallest
// id reported first, and none on a regular grid whose points sit on round multiples of the spacing.
#include <gtest/gtest.h>

#include "discretization/Discretization.hpp"
#include "discretization/DuplicatePoints.hpp"

namespace {

std::vector<double> grid(int n, double h) {
  std::vector<double> x;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) x.insert(x.end(), {i * h, j * h, k * h});
  return x;
}

}  // namespace

TEST(DuplicatePoints, NoneOnARegularGrid) {
  EXPECT_EQ(pf::findDuplicatePoints(grid(12, 1e-3), 1e-12).first, -1);
}

TEST(DuplicatePoints, FoundWithinToleranceAndReportedBySmallestId) {
  std::vector<double> x = grid(6, 1e-3);
  const int n = static_cast<int>(x.size() / 3);
  x.insert(x.end(), {x[3 * 40] + 5e-13, x[3 * 40 + 1], x[3 * 40 + 2] - 5e-13});  // point 40 again
  x.insert(x.end(), {x[3 * 7], x[3 * 7 + 1], x[3 * 7 + 2]});                     // point 7 again
  const auto d = pf::findDuplicatePoints(x, 1e-12);
  EXPECT_EQ(d.first, 7);
  EXPECT_EQ(d.second, n + 1);
}

TEST(DuplicatePoints, FoundAcrossACellFace) {
  // The cells are 1e6 x tol wide and shifted by 0.318...: put the pair on both sides of a face.
  const double tol = 1e-12, w = 1e6 * tol, face = (3.0 - 0.318309886) * w;
  const std::vector<double> x = {0, 0, 0, face - 0.4 * tol, 1, 1, face + 0.4 * tol, 1, 1};
  const auto d = pf::findDuplicatePoints(x, tol);
  EXPECT_EQ(d.first, 1);
  EXPECT_EQ(d.second, 2);
  EXPECT_EQ(pf::findDuplicatePoints({0, 0, 0, face - 2 * tol, 1, 1, face + 2 * tol, 1, 1}, tol).first, -1);
}

TEST(DuplicatePoints, ToleranceFromSpacingOrSmallestVolume) {
  EXPECT_DOUBLE_EQ(pf::duplicateTolerance(2e-3, 1.0), 2e-12);  // the spacing wins when there is one
  EXPECT_NEAR(pf::duplicateTolerance(0.0, 8e-9), 2e-12, 1e-24);   // else the cube root of the smallest volume
}
