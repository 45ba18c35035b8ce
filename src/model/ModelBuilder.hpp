#pragma once
// Builds the distributed Model from a validated input list: discretization, blocks and materials,
// Zoltan partition, ghosting, bonds, node sets and boundary conditions. Every rank calls it.
#include <Teuchos_ParameterList.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "discretization/Discretization.hpp"
#include "core/Expression.hpp"
#include "Model.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

struct Problem {
  PointCloud cloud;                                      // the whole cloud (every rank)
  std::map<std::string, std::vector<int>> nodeSets;      // cloud indices
  std::unique_ptr<Model> model;
  std::vector<NodalLoad> initialDisplacements, initialVelocities;
  std::vector<std::string> prescribedNodeSets;           // node sets carrying a Prescribed Displacement
};

Problem buildProblem(const Teuchos::ParameterList& input, const std::string& inputFile, const Communicator& comm);

}  // namespace pf
