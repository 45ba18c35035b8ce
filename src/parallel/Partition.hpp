#pragma once
// Assigns the points of a distributed cloud to MPI ranks with Zoltan's recursive coordinate bisection.
// Each rank passes its slab (buildDiscretization's part `rank` of `size`) and learns where each of its
// slab's points goes; no rank sees the whole cloud.
#include <vector>

#include "discretization/Discretization.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

// Collective. Returns the owner rank of each point of slab.
std::vector<int> partitionRcb(const PointCloud& slab, const Communicator& comm);

}  // namespace pf
