#pragma once
// Resolves the deck's node sets on the points a rank holds: Peridigm's id lists (1-based ids, or a file of
// ids), "Node Set Region" boxes or faces, the cloud's generated sets (e.g. "Left Layer") and "All".
// Result: the gids (0-based cloud indices) of the held points in each set, sorted; a set that lists
// nothing on any rank is an InputError (thrown on every rank alike, the reductions making it global).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "Discretization.hpp"
#include "input/Deck.hpp"

namespace pf {

// Sum and maximum of a value over the ranks that share the cloud; the identity for a whole cloud.
struct CloudReductions {
  std::function<double(double)> sum = [](double v) { return v; };
  std::function<double(double)> max = [](double v) { return v; };
};

std::map<std::string, std::vector<int>> resolveNodeSets(const std::vector<NodeSetSpec>& nodeSets,
                                                        const PointCloud& cloud, const std::string& inputFile,
                                                        const CloudReductions& reduce = {});

}  // namespace pf
