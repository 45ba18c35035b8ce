#include "ModelBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "core/InputError.hpp"
#include "input/InputSchema.hpp"
#include "core/MaterialEntry.hpp"
#include "discretization/NodeSets.hpp"
#include "parallel/Partition.hpp"

namespace pf {
namespace {

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

struct BlockSpec {
  std::string name, materialName;
  double horizon;
  std::shared_ptr<const Material> material;
};

// "block_3" -> 3; anything else is an input error.
int blockNumber(const std::string& name, const std::string& where) {
  if (name.rfind("block_", 0) == 0) {
    try {
      std::size_t used = 0;
      const int id = std::stoi(name.substr(6), &used);
      if (used == name.size() - 6 && id > 0) return id;
    } catch (const std::exception&) {
    }
  }
  throw InputError(where + ": 'Block Names' entry '" + name + "' is not of the form block_N");
}

}  // namespace

Problem buildProblem(const Teuchos::ParameterList& input, const std::string& inputFile, const Communicator& comm) {
  Problem pb;
  const std::string dir = directoryOf(inputFile);
  pb.cloud = buildDiscretization(input.sublist("Discretization"), inputFile, dir, maxBlockHorizon(input));
  const PointCloud& cloud = pb.cloud;
  if (cloud.size() == 0) throw InputError(inputFile + ": Discretization produced no points");

  // Blocks -> material and horizon per block id.
  std::map<int, BlockSpec> blocks;
  const Teuchos::ParameterList& blockList = input.sublist("Blocks");
  const Teuchos::ParameterList& materials = input.sublist("Materials");
  std::map<std::string, std::shared_ptr<const Material>> built;
  for (auto it = blockList.begin(); it != blockList.end(); ++it) {
    const std::string group = blockList.name(it);
    const Teuchos::ParameterList& g = blockList.sublist(group);
    const std::string where = inputFile + ": Blocks/" + group;
    const std::string matName = getText(g, "Material", "");
    if (!materials.isSublist(matName))
      throw InputError(where + ": 'Material' = '" + matName + "' is not defined under Materials");
    if (!built.count(matName)) {
      MaterialInput mi = materialInputFor(materials.sublist(matName), matName, inputFile);
      const MaterialEntry* entry = findMaterial(mi.strings.at("Material Model"));
      built[matName] = entry->create(mi);
    }
    const double horizon = getNumber(g, "Horizon");
    if (!(horizon > 0)) {
      std::ostringstream os;
      os << where << ": 'Horizon' must be positive (got " << horizon << ")";
      throw InputError(os.str());
    }
    std::istringstream names(getText(g, "Block Names", ""));
    std::string name;
    while (names >> name) {
      const int id = blockNumber(name, where);
      if (blocks.count(id)) throw InputError(where + ": block '" + name + "' is assigned twice");
      blocks[id] = BlockSpec{name, matName, horizon, built[matName]};
    }
  }

  // Every point needs a block; planar materials need a planar cloud and vice versa.
  std::vector<double> horizon(cloud.size());
  for (int p = 0; p < cloud.size(); ++p) {
    auto it = blocks.find(cloud.block[p]);
    if (it == blocks.end())
      throw InputError(inputFile + ": Blocks: the discretization has points in block_" + std::to_string(cloud.block[p]) +
                       " but no entry of Blocks names it");
    horizon[p] = it->second.horizon;
  }
  for (const auto& kv : blocks) {
    const bool planarMaterial = isPlanar(kv.second.material->dimension());
    if (planarMaterial && !cloud.planar)
      throw InputError(inputFile + ": Materials/" + kv.second.materialName +
                       ": a 2D (Plane Stress / Plane Strain) material needs a 2D discretization (all z = 0)");
    if (!planarMaterial && cloud.planar)
      throw InputError(inputFile + ": Materials/" + kv.second.materialName +
                       ": the discretization is 2D; set 'Plane Stress' or 'Plane Strain' and 'Thickness'");
  }

  std::vector<int> owner = partitionRcb(cloud.x, comm);
  auto layout = std::make_unique<DistributedLayout>(comm, cloud.x, owner, horizon, cloud.block, cloud.influence,
                                                    cloud.partialVolume ? &cloud.cell : nullptr);
  const std::vector<int>& gids = layout->gids();
  std::vector<double> x(3 * gids.size()), volume(gids.size());
  for (std::size_t i = 0; i < gids.size(); ++i) {
    for (int d = 0; d < 3; ++d) x[3 * i + d] = cloud.x[3 * gids[i] + d];
    volume[i] = cloud.volume[gids[i]];
  }
  std::vector<BlockModel> blockModels;
  for (const BlockRange& r : layout->blocks()) {
    const BlockSpec& s = blocks.at(r.blockId);
    blockModels.push_back(BlockModel{r.blockId, s.name, s.materialName, s.horizon, r.begin, r.end, s.material});
  }
  const int numOwned = layout->numOwned();
  std::unordered_map<int, int> localOf;
  for (int i = 0; i < numOwned; ++i) localOf[gids[i]] = i;
  pb.model = std::make_unique<Model>(std::move(layout), std::move(x), std::move(volume), std::move(blockModels));

  // Node sets and boundary conditions.
  const Teuchos::ParameterList& bcList = input.isSublist("Boundary Conditions")
                                             ? input.sublist("Boundary Conditions") : Teuchos::ParameterList();
  pb.nodeSets = resolveNodeSets(bcList, cloud, inputFile, dir);
  for (BoundaryCondition& bc : parseBoundaryConditions(bcList, pb.nodeSets, inputFile)) {
    NodalLoad load;
    load.coordinate = bc.coordinate;
    load.value = bc.value;
    for (int p : pb.nodeSets.at(bc.nodeSet)) {
      auto it = localOf.find(p);
      if (it != localOf.end()) load.nodes.push_back(it->second);
    }
    switch (bc.kind) {
      case BoundaryCondition::Kind::PrescribedDisplacement:
        pb.model->addPrescribedDisplacement(load);
        if (std::find(pb.prescribedNodeSets.begin(), pb.prescribedNodeSets.end(), bc.nodeSet) == pb.prescribedNodeSets.end())
          pb.prescribedNodeSets.push_back(bc.nodeSet);
        break;
      case BoundaryCondition::Kind::BodyForce: pb.model->addBodyForce(load); break;
      case BoundaryCondition::Kind::InitialDisplacement: pb.initialDisplacements.push_back(load); break;
      case BoundaryCondition::Kind::InitialVelocity: pb.initialVelocities.push_back(load); break;
    }
  }
  return pb;
}

}  // namespace pf
