// The Hilbert keys that order the points (src/SpaceFillingCurve): on the cells of a 2^k cube they are a
// permutation, and cells consecutive along the curve are face neighbours (the property the Morton order
// lacks, and why the nodes are ordered by it).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include "discretization/SpaceFillingCurve.hpp"

namespace pf {
namespace {

struct Cell {
  std::uint64_t key;
  std::array<int, 3> ijk;
};

// The cells of an s^3 cube (s a power of 2) at the origin, where the curve starts, so they are its first
// s^3 positions; sorted by key.
std::vector<Cell> sortedCells(int s) {
  std::vector<Cell> cells;
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j)
      for (int k = 0; k < s; ++k)
        cells.push_back({hilbertKey(i, j, k), {i, j, k}});
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.key < b.key; });
  return cells;
}

TEST(SpaceFillingCurve, HilbertKeysAreDistinct) {
  const std::vector<Cell> cells = sortedCells(16);
  for (std::size_t n = 1; n < cells.size(); ++n) EXPECT_LT(cells[n - 1].key, cells[n].key);
}

TEST(SpaceFillingCurve, ConsecutiveHilbertCellsAreFaceNeighbours) {
  for (int s : {2, 4, 8, 16}) {
    const std::vector<Cell> cells = sortedCells(s);
    for (std::size_t n = 1; n < cells.size(); ++n) {
      int dist = 0;
      for (int d = 0; d < 3; ++d) dist += std::abs(cells[n].ijk[d] - cells[n - 1].ijk[d]);
      ASSERT_EQ(dist, 1) << "cube " << s << ": cells " << n - 1 << " and " << n << " along the curve";
    }
  }
}

TEST(SpaceFillingCurve, KeysOfAPointCloudIgnoreAShiftAndStayDistinct) {
  // A 4^3 lattice and the same lattice shifted: the keys depend on the positions relative to the
  // bounding box only, and distinct points get distinct keys.
  std::vector<double> a, b;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double p[3] = {-1.0 + 0.5 * i, -1.0 + 0.5 * j, -1.0 + 0.5 * k};
        for (int d = 0; d < 3; ++d) {
          a.push_back(p[d]);
          b.push_back(p[d] + 7.25);
        }
      }
  const std::vector<std::uint64_t> ka = hilbertKeys(a), kb = hilbertKeys(b);
  EXPECT_EQ(ka, kb);
  std::vector<std::uint64_t> sorted = ka;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
}

}  // namespace
}  // namespace pf
