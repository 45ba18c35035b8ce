#include "BondCutter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pf {

BondCutter::BondCutter(const BondFilters& filters, const std::vector<double>& points, double reach)
    : filters_(filters) {
  if (filters.polygons.empty() || points.empty()) return;
  double hi[3];
  for (int d = 0; d < 3; ++d) lo_[d] = std::numeric_limits<double>::max(), hi[d] = -lo_[d];
  for (std::size_t p = 0; p < points.size(); p += 3)
    for (int d = 0; d < 3; ++d) lo_[d] = std::min(lo_[d], points[p + d]), hi[d] = std::max(hi[d], points[p + d]);
  // Cells at least the longest bond wide, so a bond's box meets at most 2 per direction; no more cells than
  // a few per polygon, so a fine lattice with a coarse shell mesh keeps a small grid.
  const double cap = std::cbrt(8.0 * static_cast<double>(filters.polygons.size()) + 64.0);
  for (int d = 0; d < 3; ++d) {
    const double extent = hi[d] - lo_[d];
    dims_[d] = std::max(1L, std::min(static_cast<long>(extent / reach) + 1, static_cast<long>(cap) + 1));
    cell_[d] = std::max(extent / static_cast<double>(dims_[d]), reach);
  }
  // Each polygon's box (grown by a margin over the 1e-14 edge tolerance of the test) binned into the cells it
  // meets; one outside the points' box is dropped.
  std::vector<std::array<long, 6>> range;
  std::vector<int> kept;
  for (std::size_t k = 0; k < filters.polygons.size(); ++k) {
    const PolygonPatch& s = filters.polygons[k];
    double pmin[3], pmax[3];
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
      pmin[d] = pmax[d] = s.v[0][d];
      for (int c = 1; c < s.corners; ++c) pmin[d] = std::min(pmin[d], s.v[c][d]), pmax[d] = std::max(pmax[d], s.v[c][d]);
      const double margin = 1e-9 * (pmax[d] - pmin[d] + reach + std::fabs(pmin[d]) + std::fabs(pmax[d]));
      pmin[d] -= margin, pmax[d] += margin;
      inside = inside && pmax[d] >= lo_[d] && pmin[d] <= hi[d];
    }
    if (!inside) continue;
    kept.push_back(static_cast<int>(k));
    range.push_back({cellOf(pmin[0], 0), cellOf(pmax[0], 0), cellOf(pmin[1], 1), cellOf(pmax[1], 1),
                     cellOf(pmin[2], 2), cellOf(pmax[2], 2)});
  }
  start_.assign(dims_[0] * dims_[1] * dims_[2] + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {  // count, then fill
    std::vector<long> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const std::array<long, 6>& r = range[k];
      for (long z = r[4]; z <= r[5]; ++z)
        for (long y = r[2]; y <= r[3]; ++y)
          for (long x = r[0]; x <= r[1]; ++x) {
            const long c = (z * dims_[1] + y) * dims_[0] + x;
            if (pass == 0) ++start_[c + 1];
            else polygon_[fill[c]++] = kept[k];
          }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
      polygon_.resize(start_.back());
    }
  }
}

long BondCutter::cellOf(double c, int d) const {
  const long k = static_cast<long>(std::floor((c - lo_[d]) / cell_[d]));
  return std::min(std::max(k, 0L), dims_[d] - 1);
}

bool BondCutter::cuts(const double* p0, const double* p1) const {
  for (const PlanePatch& s : filters_.planes)
    if (pf::cuts(s, p0, p1)) return true;
  for (const DiskPatch& s : filters_.disks)
    if (pf::cuts(s, p0, p1)) return true;
  if (polygon_.empty()) return false;
  long r[6];
  for (int d = 0; d < 3; ++d) r[2 * d] = cellOf(std::min(p0[d], p1[d]), d), r[2 * d + 1] = cellOf(std::max(p0[d], p1[d]), d);
  for (long z = r[4]; z <= r[5]; ++z)
    for (long y = r[2]; y <= r[3]; ++y)
      for (long x = r[0]; x <= r[1]; ++x) {
        const long c = (z * dims_[1] + y) * dims_[0] + x;
        for (long k = start_[c]; k < start_[c + 1]; ++k)
          if (pf::cuts(filters_.polygons[polygon_[k]], p0, p1)) return true;
      }
  return false;
}

void removeCutBonds(BondFamily& family, const std::vector<double>& points, const BondFilters& filters, double reach) {
  if (filters.empty()) return;
  const BondCutter cutter(filters, points, reach);
  keepBonds(family, [&](int i, int j) { return !cutter.cuts(&points[3 * i], &points[3 * j]); });
}

}  // namespace pf
