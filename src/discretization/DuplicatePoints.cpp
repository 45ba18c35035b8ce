#include "DuplicatePoints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace pf {

double duplicateTolerance(double spacing, double smallestVolume) {
  return spacing > 0 ? 1e-9 * spacing : 1e-9 * std::cbrt(smallestVolume);
}

namespace {

using CellKey = std::array<long long, 3>;

// Cells many times the tolerance wide, shifted by an irrational fraction so that the points of a regular
// grid (at round multiples of the spacing) do not sit on cell faces: a point then needs only its own
// cell, and the neighbour cells only when it lies within tol of a face.
struct DuplicateCells {
  double width, tol;
  CellKey key(const double* p, const int offset[3]) const {
    CellKey k;
    for (int d = 0; d < 3; ++d) k[d] = static_cast<long long>(std::floor(p[d] / width + 0.318309886)) + offset[d];
    return k;
  }
  // -1, 0, +1 per axis: whether p is within tol of its cell's lower or upper face.
  int nearFace(const double* p, int d) const {
    const double s = p[d] / width + 0.318309886, f = s - std::floor(s);
    return f * width <= tol ? -1 : ((1.0 - f) * width <= tol ? 1 : 0);
  }
};

bool same(const double* a, const double* b, double tol) {
  return std::fabs(a[0] - b[0]) <= tol && std::fabs(a[1] - b[1]) <= tol && std::fabs(a[2] - b[2]) <= tol;
}

}  // namespace

std::pair<int, int> findDuplicatePoints(const std::vector<double>& x, double tol) {
  const int n = static_cast<int>(x.size() / 3);
  if (n < 2 || !(tol > 0)) return {-1, -1};
  const DuplicateCells cells{1e6 * tol, tol};
  const int none[3] = {0, 0, 0};
  std::vector<std::pair<CellKey, int>> sorted(n);
  for (int p = 0; p < n; ++p) sorted[p] = {cells.key(&x[3 * p], none), p};
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < n; ++i) {
    const double* xi = &x[3 * i];
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) lo[d] = std::min(0, cells.nearFace(xi, d)), hi[d] = std::max(0, cells.nearFace(xi, d));
    int best = -1;  // the smallest other id at i's place, so the reported pair does not depend on the sort
    for (int a = lo[0]; a <= hi[0]; ++a)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int c = lo[2]; c <= hi[2]; ++c) {
          const int off[3] = {a, b, c};
          const CellKey k = cells.key(xi, off);
          for (auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(k, -1));
               it != sorted.end() && it->first == k; ++it)
            if (it->second != i && same(xi, &x[3 * it->second], tol) && (best < 0 || it->second < best))
              best = it->second;
        }
    if (best >= 0) return {std::min(i, best), std::max(i, best)};
  }
  return {-1, -1};
}

std::string duplicateMessage(const std::string& inputFile, int i, int j, const double* p) {
  char msg[256];
  std::snprintf(msg, sizeof msg, ": Discretization: points %d and %d have the same coordinates (%g, %g, %g)", i + 1,
                j + 1, p[0], p[1], p[2]);
  return inputFile + msg;
}

}  // namespace pf
