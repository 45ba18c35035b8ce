#pragma once
// Builds the distributed Model from a validated Deck: discretization, blocks and materials, Zoltan
// partition, ghosting, bonds, node sets and boundary conditions. Every rank calls it.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "discretization/Discretization.hpp"
#include "input/Deck.hpp"
#include "Model.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

struct Problem {
  PointCloud cloud;                                      // the cloud's metadata only (spacing, planar, numGlobal)
  std::map<std::string, std::vector<int>> nodeSets;      // per set: the gids of this rank's owned points in it
  std::unique_ptr<Model> model;
  std::vector<NodalLoad> initialDisplacements, initialVelocities;
  std::vector<std::string> prescribedNodeSets;           // node sets carrying a Prescribed Displacement
};

Problem buildProblem(const Deck& deck, const Communicator& comm);

}  // namespace pf
