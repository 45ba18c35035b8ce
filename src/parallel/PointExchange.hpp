#pragma once
// Moves points of a distributed cloud between ranks (the set-up's only point traffic: a slab to its
// partition owners, and owned points to the ranks that ghost them). A point travels with its gid,
// coordinates, volume, block and generated node-set membership; what a rank receives is sorted by gid.
#include <vector>

#include "discretization/Discretization.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

// Collective. Sends point index[k] of `points` to rank dest[k] (a point may go to several ranks, or to
// this one). Returns the points received, ascending by gid, with points' metadata (spacing, numGlobal...)
// and every generated node set's name; from (if not null) gets the sending rank of each.
PointCloud exchangePoints(const Communicator& comm, const PointCloud& points, const std::vector<int>& index,
                          const std::vector<int>& dest, std::vector<int>* from = nullptr);

// Collective. Each rank's bounding box of its points grown by pad is shared; this rank sends every other rank its
// points inside that rank's box. Returns the points received (from: their owners), as exchangePoints. The
// neighbour points a rank needs, for any reach up to pad, without any rank seeing the whole cloud.
PointCloud exchangeNearBoxes(const Communicator& comm, const PointCloud& points, double pad,
                             std::vector<int>* from = nullptr);

// The same cloud without points: its metadata and generated node-set names only.
PointCloud withoutPoints(const PointCloud& cloud);

}  // namespace pf
