#include "NeighborSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "PartialVolume.hpp"

namespace pf {

namespace {

// The points counting-sorted into a box grid of cells at least hmax wide, so a ball of radius hmax
// around any point meets at most 27 cells.
struct CellGrid {
  double lo[3], hi[3], cell[3];
  long dims[3];
  std::vector<long> start;  // points of cell c: sorted[start[c] .. start[c + 1])
  std::vector<int> sorted;

  CellGrid(const std::vector<double>& points, double hmax) {
    const int n = static_cast<int>(points.size() / 3);
    for (int d = 0; d < 3; ++d) { lo[d] = std::numeric_limits<double>::max(); hi[d] = -lo[d]; }
    for (int p = 0; p < n; ++p)
      for (int d = 0; d < 3; ++d) { lo[d] = std::min(lo[d], points[3 * p + d]); hi[d] = std::max(hi[d], points[3 * p + d]); }
    long total = 1;
    for (int d = 0; d < 3; ++d) {
      dims[d] = std::max(1L, static_cast<long>((hi[d] - lo[d]) / hmax) + 1);
      total *= dims[d];
    }
    if (total > 4L * n + 64) {  // sparse cloud: coarsen cells so the grid stays O(N)
      const double f = std::cbrt(static_cast<double>(total) / (4.0 * n + 64));
      total = 1;
      for (int d = 0; d < 3; ++d) { dims[d] = std::max(1L, static_cast<long>(dims[d] / f)); total *= dims[d]; }
    }
    // A flat direction (2D clouds) gets one cell as wide as the horizon, so cell ranges stay finite.
    for (int d = 0; d < 3; ++d) cell[d] = std::max((hi[d] - lo[d]) / dims[d], hmax);
    start.assign(total + 1, 0);
    std::vector<long> cellIndex(n);
    for (int p = 0; p < n; ++p) {
      const double* x = &points[3 * p];
      cellIndex[p] = (cellOf(x, 2) * dims[1] + cellOf(x, 1)) * dims[0] + cellOf(x, 0);
      ++start[cellIndex[p] + 1];
    }
    for (long c = 0; c < total; ++c) start[c + 1] += start[c];
    sorted.resize(n);
    std::vector<long> fill(start.begin(), start.end() - 1);
    for (int p = 0; p < n; ++p) sorted[fill[cellIndex[p]]++] = p;
  }

  long cellOf(const double* p, int d) const {
    long c = static_cast<long>((p[d] - lo[d]) / cell[d]);
    return std::min(std::max(c, 0L), dims[d] - 1);
  }

  // row = every point j != i with |x_j - x_i|^2 <= h2, in cell order (callers sort).
  void within(const std::vector<double>& points, int i, double h, double h2, std::vector<int>& row) const {
    const double* xi = &points[3 * i];
    long cmin[3], cmax[3];
    for (int d = 0; d < 3; ++d) {
      const double a = std::floor((xi[d] - h - lo[d]) / cell[d]), b = std::floor((xi[d] + h - lo[d]) / cell[d]);
      cmin[d] = static_cast<long>(std::max(0.0, a));
      cmax[d] = static_cast<long>(std::min(static_cast<double>(dims[d] - 1), b));
    }
    row.clear();
    for (long cz = cmin[2]; cz <= cmax[2]; ++cz)
      for (long cy = cmin[1]; cy <= cmax[1]; ++cy)
        for (long cx = cmin[0]; cx <= cmax[0]; ++cx) {
          const long c = (cz * dims[1] + cy) * dims[0] + cx;
          for (long s = start[c]; s < start[c + 1]; ++s) {
            const int j = sorted[s];
            if (j == i) continue;
            const double d0 = points[3 * j] - xi[0], d1 = points[3 * j + 1] - xi[1], d2 = points[3 * j + 2] - xi[2];
            if (d0 * d0 + d1 * d1 + d2 * d2 <= h2) row.push_back(j);
          }
        }
  }
};

}  // namespace

void buildFamilies(const std::vector<double>& points, int numQueries, const std::vector<double>& horizonIn,
                   BondFamily& family, const std::array<double, 3>* gridCell, const std::array<double, 3>* box) {
  // A box neighbourhood is searched within the ball around the box, then filtered per direction.
  std::vector<double> horizon = horizonIn;
  if (box) {
    const double r = std::sqrt((*box)[0] * (*box)[0] + (*box)[1] * (*box)[1] + (*box)[2] * (*box)[2]);
    for (double& h : horizon) h = std::max(h, r);
  }
  const int n = static_cast<int>(points.size() / 3);
  family.offsets.assign(1, 0);
  family.neighbors.clear();
  family.refLength.clear();
  family.fraction.clear();
  family.numNodes = n;
  if (numQueries == 0) return;
  double hmax = 0.0;
  for (int i = 0; i < numQueries; ++i) hmax = std::max(hmax, horizon[i]);
  if (!(hmax > 0)) throw std::invalid_argument("buildFamilies: horizon must be positive");
  // With partial volumes a centre up to half a cell diagonal beyond the horizon still has part of its
  // cell inside: search that far, keep the bonds whose fraction is positive.
  const double reach = gridCell ? halfCellDiagonal(*gridCell) : 0.0;
  PartialVolumeTable table(gridCell ? *gridCell : std::array<double, 3>{});
  hmax += reach;
  const CellGrid grid(points, hmax);

  std::vector<int> row;
  for (int i = 0; i < numQueries; ++i) {
    const double* xi = &points[3 * i];
    const double h = horizon[i] + reach;
    // Peridigm's rule is |xi|^2 <= delta^2 (VTK's kd-tree, no tolerance). A centre on the horizon is kept
    // whatever its squares round to (a lattice at delta = 3 dx, 15 dx): a tie tolerance of 1e-13 of delta^2,
    // some hundred ulps, well below the 2e-12 by which Peridigm's MultipleHorizons deck puts its horizons
    // (1 -/+ 1e-12 on a unit lattice) either side of the neighbours it must drop or keep.
    grid.within(points, i, h, h * h * (1.0 + (gridCell ? 1e-10 : 1e-13)), row);
    std::sort(row.begin(), row.end());
    for (int j : row) {
      const double d0 = points[3 * j] - xi[0], d1 = points[3 * j + 1] - xi[1], d2 = points[3 * j + 2] - xi[2];
      if (box && !(std::fabs(d0) < (*box)[0] && std::fabs(d1) < (*box)[1] && std::fabs(d2) < (*box)[2])) continue;
      if (gridCell) {
        const double f = table.fraction({d0, d1, d2}, horizon[i]);
        if (!(f > 1e-12)) continue;  // corner contacts: no measurable share
        family.fraction.push_back(f);
      }
      family.neighbors.push_back(j);
      family.refLength.push_back(std::sqrt(d0 * d0 + d1 * d1 + d2 * d2));
    }
    family.offsets.push_back(static_cast<int>(family.neighbors.size()));
  }
}

}  // namespace pf
