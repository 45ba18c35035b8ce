#pragma once
// Node sets named in "Boundary Conditions": Peridigm string parameters (1-based ids, or a file of ids
// relative to the deck), "Node Set Region" sub-lists (box bounds or a face of the cloud), the cloud's
// generated sets (e.g. "Left Layer") and "All". Result: 0-based, sorted, unique; empty is an InputError.
#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "Discretization.hpp"

namespace pf {

std::map<std::string, std::vector<int>> resolveNodeSets(const Teuchos::ParameterList& boundaryConditions,
                                                        const PointCloud& cloud, const std::string& inputFile,
                                                        const std::string& inputDir);

}  // namespace pf
