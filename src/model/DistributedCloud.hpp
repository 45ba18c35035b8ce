#pragma once
// The set-up's whole-cloud questions answered without a whole cloud on any rank: this rank's slab of the
// discretization (a Text File read in byte ranges), the cloud's block ids, and coincident points.
// Collective; an InputError on any rank is thrown on every rank (the lowest failing rank's message).
#include <set>
#include <string>

#include "discretization/Discretization.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedLayout.hpp"

namespace pf {

// Points [N*rank/size, N*(rank+1)/size) of the cloud in cloud order, gids set.
PointCloud buildSlab(const DiscretizationSpec& spec, const std::string& inputFile, const Communicator& comm);

// Every block id of the cloud, on every rank.
std::set<int> blockIdsOf(const PointCloud& slab, const Communicator& comm);

// InputError "points i and j have the same coordinates" for the pair with the smallest ids (as a whole-cloud
// search finds it): two coincident points are always in one rank's owned and ghost points.
void requireDistinctPoints(const DistributedLayout& layout, const std::vector<double>& overlapX,
                           const std::vector<double>& overlapVolume, double spacing, const std::string& inputFile);

}  // namespace pf
