#pragma once
// Assigns every point of a replicated point cloud to an MPI rank with Zoltan's recursive coordinate
// bisection. Every rank passes the same coordinates and gets the same owner array back.
#include <vector>

#include "parallel/Communicator.hpp"

namespace pf {

// coords: 3 per point (the whole cloud, identical on all ranks). Returns owner rank per point.
std::vector<int> partitionRcb(const std::vector<double>& coords, const Communicator& comm);

}  // namespace pf
