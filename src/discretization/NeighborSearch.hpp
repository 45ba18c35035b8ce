#pragma once
// O(N) cell-list search for peridynamic families on the reference configuration. Points at distance
// <= horizon (with a 1e-10 relative tolerance so lattice ties are included on every rank alike) are
// neighbours; a point is never its own neighbour.
#include <array>
#include <vector>

#include "core/BondFamily.hpp"

namespace pf {

// points: 3 per point (all candidates, e.g. owned then ghost); the first numQueries points are the
// ones whose families are built; horizon: one per query point. Fills offsets/neighbors/refLength.
// Neighbours of each row are sorted by index for a deterministic bond order.
// gridCell (optional): the grid's cell edge lengths (0 in a flat direction) for partial volumes: every point
// whose cell overlaps the horizon ball is a neighbour, and family.fraction gets the share of its cell
// inside the ball (PartialVolume.hpp). Without it family.fraction stays empty.
// box (optional, not with gridCell): Peridigm's PdQuickGrid neighbourhood without "NeighborhoodType" (its
// NoOp norm): j is a neighbour of i iff |x_j - x_i| < box[d] in each direction d, whatever the distance
// (QuickGridNeighbourhood.hpp gives box); horizon then only feeds the influence function.
void buildFamilies(const std::vector<double>& points, int numQueries, const std::vector<double>& horizon,
                   BondFamily& family, const std::array<double, 3>* gridCell = nullptr,
                   const std::array<double, 3>* box = nullptr);

}  // namespace pf
