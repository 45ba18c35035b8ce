#pragma once
// Which bonds a set of bond filters (core/BondFilter.hpp) cuts, for the points of one rank (owned and ghosts).
// An Exodus Mesh filter has one polygon per element, hundreds or thousands: they are binned in a grid of
// cells about the longest bond wide over the points' bounding box (a polygon outside it can cut no bond,
// which lies inside the box), so a bond is tested against the polygons of the few cells its own box meets.
// Planes and disks, a few per deck, are tested directly.
#include <vector>

#include "core/BondFamily.hpp"
#include "core/BondFilter.hpp"

namespace pf {

class BondCutter {
 public:
  // points: 3 per point, every bond end; reach: the longest bond (> 0).
  BondCutter(const BondFilters& filters, const std::vector<double>& points, double reach);
  // Whether the bond from p0 to p1 (p0 the point whose family holds it) crosses a filter.
  bool cuts(const double* p0, const double* p1) const;

 private:
  long cellOf(double c, int d) const;
  const BondFilters& filters_;
  double lo_[3] = {0, 0, 0}, cell_[3] = {1, 1, 1};
  long dims_[3] = {1, 1, 1};
  std::vector<long> start_;  // polygons of cell c: polygon_[start_[c] .. start_[c + 1])
  std::vector<int> polygon_;
};

// Drops from family (rows of owned points over points, neighbours indexing points) every bond the filters cut;
// reach: the longest bond. No filters: nothing is done.
void removeCutBonds(BondFamily& family, const std::vector<double>& points, const BondFilters& filters, double reach);

}  // namespace pf
