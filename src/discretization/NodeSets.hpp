#pragma once
// Resolves the deck's node sets on the cloud: Peridigm's id lists (1-based ids, or a file of ids),
// "Node Set Region" boxes or faces, the cloud's generated sets (e.g. "Left Layer") and "All".
// Result: 0-based, sorted, unique cloud indices; a set that lists nothing is an InputError.
#include <map>
#include <string>
#include <vector>

#include "Discretization.hpp"
#include "input/Deck.hpp"

namespace pf {

std::map<std::string, std::vector<int>> resolveNodeSets(const std::vector<NodeSetSpec>& nodeSets,
                                                        const PointCloud& cloud, const std::string& inputFile);

}  // namespace pf
