#include "ModelBuilder.hpp"

#include "model/ContactBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>
#include <unordered_map>

#include "core/ElasticModuli.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "core/MaterialEntry.hpp"
#include "discretization/NodeSets.hpp"
#include "model/DistributedCloud.hpp"
#include "model/BlockRules.hpp"
#include "model/LoadedField.hpp"
#include "model/PointHorizons.hpp"
#include "model/PositionAwareInfluence.hpp"
#include "model/PressureLoad.hpp"
#include "parallel/Collective.hpp"
#include "parallel/Partition.hpp"
#include "parallel/PointExchange.hpp"

namespace pf {
namespace {

// The bulk modulus of a material: its `Bulk Modulus`, or from two of Peridigm's elastic constants
// (core/ElasticModuli.hpp); 0 if it has neither (Diffusion).
double bulkModulusOf(const MaterialSpec& m) {
  int given = 0;
  for (const char* k : {"Bulk Modulus", "Shear Modulus", "Young's Modulus", "Poisson's Ratio"}) given += m.values.has(k);
  if (given >= 2) return elasticModuliFrom(m.values).bulk;
  return m.values.has("Bulk Modulus") ? m.values.get("Bulk Modulus") : 0.0;
}

// Block id -> its group's material and horizon. Peridigm's group "default" takes every block of the
// cloud that no other group names (none left: the group is unused).
std::map<int, BlockSpec> blockSpecs(const Deck& deck, const std::set<int>& cloudBlocks) {
  requireUniformInterfaceAware(deck);
  std::map<int, BlockSpec> blocks;
  std::map<std::string, std::shared_ptr<const Material>> built;
  std::map<std::string, std::vector<std::shared_ptr<const FieldOperator>>> operators;
  auto materialOf = [&](const std::string& name) {
    if (!built.count(name)) {
      const MaterialSpec& m = deck.material(name);
      built[name] = m.entry->create(m.values);
      if (m.entry->createOperators)
        for (auto& op : m.entry->createOperators(m.values)) operators[name].push_back(std::move(op));
    }
    return built[name];
  };
  auto specOf = [&](const BlockGroupSpec& g, int id) {
    const DamageModelSpec* d = deck.damageModel(g.damageModel);
    if (d && d->tensileStrength > 0.0 && !materialOf(g.material)->breaksBondsByStress())
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Damage Model' = '" + g.damageModel + "' (" + d->model +
                       "): material '" + g.material + "' (" + deck.material(g.material).entry->model +
                       ") has no Cauchy stress per point; Maximum Principal Stress works with the correspondence models");
    if (d && (d->criticalStretch > 0.0 || d->stretchOfTime) && !materialOf(g.material)->breaksBonds())
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Damage Model' = '" + g.damageModel + "': material '" +
                       g.material + "' (" + deck.material(g.material).entry->model +
                       ") does not break bonds (docs/materials.md, \"Bond damage\", lists the models that do)");
    if (d && d->thermalExpansion >= 0.0) {
      const ParameterValues& mv = deck.material(g.material).values;
      const double alpha = mv.has("Thermal Expansion Coefficient") ? mv.get("Thermal Expansion Coefficient") : 0.0;
      if (d->thermalExpansion != alpha) {
        char values[120];
        std::snprintf(values, sizeof values, " = %g differs from the material's %g", d->thermalExpansion, alpha);
        throw InputError(deck.file + ": Damage Models/" + g.damageModel + ": 'Thermal Expansion Coefficient'" + values +
                         " (material '" + g.material + "'); Periforge breaks bonds on the stretch less the material's "
                         "own thermal strain, so give the same value or leave it out");
      }
    }
    if (g.horizonExpression && !materialOf(g.material)->takesPointHorizon())
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Horizon' is an expression in x, y, z (a horizon that varies by "
                       "point); material '" + g.material + "' (" + deck.material(g.material).entry->model +
                       ") takes one horizon per block, as in Peridigm: only the correspondence models take a horizon per point");
    if (g.horizonExpression && operators.count(g.material) && !operators[g.material].empty())
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Horizon' is an expression in x, y, z; the heat terms of "
                       "material '" + g.material + "' (conduction, heat capacity, plastic heating) take one horizon per block");
    if (g.horizonExpression && deck.contact.given)
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Horizon' is an expression in x, y, z; contact takes one "
                       "horizon per block (as Peridigm: variable horizon not supported by contact)");
    if (g.ndoBand && !materialOf(g.material)->supportsSurfaceBand())
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Surface Correction' = 'NDO Band': material '" +
                       g.material + "' (" + deck.material(g.material).entry->model +
                       ") has no first Piola stress; the band works with the correspondence models");
    BlockSpec spec;
    spec.name = "block_" + std::to_string(id);
    spec.materialName = g.material;
    spec.horizon = g.horizon;
    spec.material = materialOf(g.material);
    spec.criticalStretch = d ? d->criticalStretch : 0.0;
    spec.ndoBand = g.ndoBand;
    spec.tensileStrength = d ? d->tensileStrength : 0.0;
    spec.horizonExpression = g.horizonExpression;
    spec.group = g.name;
    if (operators.count(g.material)) spec.fieldOperators = operators[g.material];
    if (d) spec.stretchOfTime = d->stretchOfTime;
    spec.bulkModulus = bulkModulusOf(deck.material(g.material));
    if (d && !d->initialBreaks.empty()) spec.initialBreaks = std::make_shared<const BondFilters>(d->initialBreaks);
    return spec;
  };
  for (const BlockGroupSpec& g : deck.blocks)
    for (int id : g.blockIds) blocks[id] = specOf(g, id);
  for (const BlockGroupSpec& g : deck.blocks) {
    if (!g.isDefault) continue;
    for (int id : cloudBlocks)
      if (!blocks.count(id)) blocks[id] = specOf(g, id);
  }
  return blocks;
}

// Peridigm's PdQuickGrid box (QuickGrid.cxx, Spec1D::getCellNeighborhoodSize): n = floor(δ/dx), plus one
// if the remainder is at least 1/2, at most the cell count; returned as half-widths (n + 1/2) dx, so that
// lattice offsets k dx with k <= n fall inside with room for round-off.
std::array<double, 3> quickGridBox(const DiscretizationSpec& d, double horizon) {
  std::array<double, 3> box{};
  for (int a = 0; a < 3; ++a) {
    const double dx = d.length[a] / d.count[a], ratio = horizon / dx;
    std::size_t n = static_cast<std::size_t>(ratio);
    if (std::fabs(ratio - static_cast<double>(n)) >= 0.5) n += 1;
    n = std::min(n, static_cast<std::size_t>(d.count[a]));
    box[a] = (static_cast<double>(n) + 0.5) * dx;
  }
  return box;
}

// A Text File mesh, or an Exodus or Gmsh mesh of 3D elements, is 3D unless it is flat (every point at z = 0: for Exodus,
// one layer of elements centred on z = 0, as Peridigm's 2D decks mesh a plate) and every block's material is 2D:
// then it is the 2D discretization those materials need (the volumes already hold the thickness).
void adoptFlatMesh(const DiscretizationSpec& spec, PointCloud& cloud, const std::map<int, BlockSpec>& blocks,
                   const Communicator& comm) {
  const bool file = spec.type == DiscretizationSpec::Type::TextFile || spec.isElementMesh();
  if (!file || cloud.planar) return;
  double raised = 0.0;
  for (int p = 0; p < cloud.size(); ++p)
    if (cloud.x[3 * p + 2] != 0.0) raised = 1.0;
  if (comm.max(raised) > 0.0) return;
  for (const auto& kv : blocks)
    if (!isPlanar(kv.second.material->dimension())) return;
  cloud.planar = true;
}

// A Pressure condition as body forces on its layer, or follower tractions of the band (model/PressureLoad.hpp).
void addPressure(Model& model, const ConditionSpec& bc, const std::vector<int>& nodes, double spacing,
                 const std::string& inputFile) {
  const std::string context = inputFile + ": Boundary Conditions/" + bc.name;
  const double h = bc.layerThickness > 0 ? bc.layerThickness : spacing;
  if (!(h > 0))
    throw InputError(context + ": 'Layer Thickness' is needed: the discretization has no grid spacing to default to");
  for (NodalLoad& l : pressureLoads(model, nodes, bc.value, h, context, bc.follower))
    bc.follower ? model.addFollowerPressure(std::move(l)) : model.addBodyForce(std::move(l));
}

// Heat Flux / Convection on the layer of points the node set holds (model/FieldSurface.hpp).
void addSurfaceHeat(Model& model, const ConditionSpec& bc, NodalLoad load, double spacing, const std::string& inputFile) {
  const double l = bc.layerThickness > 0 ? bc.layerThickness : spacing;
  if (!(l > 0))
    throw InputError(inputFile + ": Boundary Conditions/" + bc.name + ": 'Layer Thickness' is needed: the "
                     "discretization has no grid spacing to default to");
  load.coordinate = 0;
  model.addField("Temperature");
  FieldSurface& surface = model.fields().surface("Temperature");
  if (bc.kind == ConditionSpec::Kind::HeatFlux)
    surface.addFlux(std::move(load), l);
  else
    surface.addConvection(std::move(load), bc.transferCoefficient, l);
}

// Points without bonds carry no force and make the stiffness singular: one line, with the first of them.
void warnPointsWithoutBonds(const Model& model, const std::string& inputFile) {
  double count = 0, first = -1e300;  // first: -(smallest 1-based id), reduced as a max
  for (int i = 0; i < model.numOwned(); ++i)
    if (model.numNeighbors(i) == 0) {
      ++count;
      first = std::max(first, -static_cast<double>(model.layout().gids()[i] + 1));
    }
  count = model.sum(count);
  first = model.max(first);
  if (count == 0) return;
  char msg[200];
  std::snprintf(msg, sizeof msg, ": %.0f point(s) have no bonds (first: point %.0f); they carry no load", count,
                -first);
  warn(inputFile + msg);
}

// Collective. A body that starts behind its wall (a reversed normal, a plane through the body) would be
// flattened onto the plane in the first step and fail there with an inverted family: an input error now.
// Points on the plane within a millionth of the horizon are in front (a wall touching the body is the usual set-up).
void requireInFrontOfWall(const Deck& deck, const RigidWallSpec& spec, const RigidWall& wall, const Model& model) {
  const std::vector<double>& x = model.coordinates();
  double behind = 0.0, depth = 0.0;
  for (int i : wall.nodes) {
    double gap = 0.0;
    for (int c = 0; c < 3; ++c) gap += (x[3 * i + c] - wall.point[c]) * wall.normal[c];
    if (gap < -1e-6 * deck.maxHorizon()) behind += 1.0, depth = std::max(depth, -gap);
  }
  behind = model.sum(behind);
  depth = model.max(depth);
  if (behind == 0.0) return;
  char msg[300];
  std::snprintf(msg, sizeof msg, "%.0f point(s) of node set '%s' start behind the wall (up to %g behind its plane); the "
                "'Normal' points to the side the body stays on: is it reversed, or does the plane cut the body?",
                behind, spec.nodeSet.c_str(), depth);
  throw InputError(deck.file + ": Boundary Conditions/" + spec.name + ": " + msg);
}

// The deck's Rigid Walls on the owned points of their node sets (cloud index -> owned-local: localOf).
void addRigidWalls(const Deck& deck, Problem& pb, const std::unordered_map<int, int>& localOf) {
  for (const RigidWallSpec& w : deck.walls) {
    RigidWall wall{w.name, w.point, w.normal, {}};
    for (int p : pb.nodeSets.at(w.nodeSet)) {
      auto it = localOf.find(p);
      if (it != localOf.end()) wall.nodes.push_back(it->second);
    }
    requireInFrontOfWall(deck, w, wall, *pb.model);
    pb.model->addRigidWall(std::move(wall));
  }
}

// Every point needs a block (the lowest rank's first such point is the cloud's first); planar materials
// need a planar cloud and vice versa.
void requireBlocksAndDimension(const Deck& deck, PointCloud& slab, const std::map<int, BlockSpec>& blocks,
                               const Communicator& comm) {
  const std::string& inputFile = deck.file;
  collectively(comm, [&] {
    for (int p = 0; p < slab.size(); ++p)
      if (!blocks.count(slab.block[p]))
        throw InputError(inputFile + ": Blocks: the discretization has points in block_" + std::to_string(slab.block[p]) +
                         " but no entry of Blocks names it");
  });
  adoptFlatMesh(deck.discretization, slab, blocks, comm);
  for (const auto& kv : blocks) {
    const bool planarMaterial = isPlanar(kv.second.material->dimension());
    if (planarMaterial && !slab.planar)
      throw InputError(inputFile + ": Materials/" + kv.second.materialName +
                       ": a 2D (Plane Stress / Plane Strain) material needs a 2D discretization (all z = 0)");
    if (!planarMaterial && slab.planar) {
      const MaterialEntry& entry = *deck.material(kv.second.materialName).entry;
      bool has2D = false;
      for (const ParameterSpec& p : entry.parameters) has2D = has2D || p.name == "Plane Stress" || p.name == "Plane Strain";
      throw InputError(inputFile + ": Materials/" + kv.second.materialName + ": the discretization is 2D; " +
                       (has2D ? std::string("set 'Plane Stress' or 'Plane Strain' and 'Thickness'")
                              : "material model '" + entry.model + "' is 3D only" +
                                    (entry.model == "Diffusion" ? " (as Peridigm's); a solid with 'Thermal Conductivity' "
                                                                  "conducts heat in 2D"
                                                                : "")));
    }
  }
}

// The deck's boundary conditions on the owned points of their node sets (cloud index -> owned-local: localOf).
void addConditions(const Deck& deck, Problem& pb, const std::unordered_map<int, int>& localOf, double spacing) {
  const std::string& inputFile = deck.file;
  for (const ConditionSpec& bc : deck.conditions) {
    NodalLoad load;
    load.coordinate = bc.coordinate;
    load.value = bc.value;
    for (int p : pb.nodeSets.at(bc.nodeSet)) {
      auto it = localOf.find(p);
      if (it != localOf.end()) load.nodes.push_back(it->second);
    }
    switch (bc.kind) {
      case ConditionSpec::Kind::PrescribedDisplacement:
        pb.model->addPrescribedDisplacement(load, bc.atInitialTime);
        if (std::find(pb.prescribedNodeSets.begin(), pb.prescribedNodeSets.end(), bc.nodeSet) == pb.prescribedNodeSets.end())
          pb.prescribedNodeSets.push_back(bc.nodeSet);
        break;
      case ConditionSpec::Kind::BodyForce: pb.model->addBodyForce(load); break;
      case ConditionSpec::Kind::Pressure: addPressure(*pb.model, bc, load.nodes, spacing, inputFile); break;
      case ConditionSpec::Kind::InitialDisplacement: pb.initialDisplacements.push_back(load); break;
      case ConditionSpec::Kind::InitialVelocity: pb.initialVelocities.push_back(load); break;
      case ConditionSpec::Kind::PrescribedTemperature:
        load.coordinate = 0;
        pb.model->addField("Temperature");
        pb.model->fields().addPrescribed("Temperature", load);
        break;
      case ConditionSpec::Kind::InitialTemperature:
        load.coordinate = 0;
        pb.model->addField("Temperature");
        pb.model->fields().addInitial("Temperature", load);
        break;
      case ConditionSpec::Kind::HeatFlux:
      case ConditionSpec::Kind::Convection: addSurfaceHeat(*pb.model, bc, load, spacing, inputFile); break;
    }
  }
}

// Each owned point's horizon (model/PointHorizons.hpp) and what the builder needs of it.
struct OwnedHorizons {
  std::vector<double> value;        // per point of the rank's owned cloud
  bool uniform = true;              // one value across the whole body
  std::map<int, double> largestOf;  // expression blocks: the largest of their points' (all ranks), their fam.horizon
};

// Collective. An expression block's value <= 0 or not finite at a point is an InputError on every rank.
OwnedHorizons ownedHorizons(const Deck& deck, const std::map<int, BlockSpec>& blocks, const PointCloud& owned,
                            const Communicator& comm) {
  std::map<int, HorizonRule> ruleOf;
  for (const auto& kv : blocks)
    ruleOf[kv.first] = {kv.second.horizon, kv.second.horizonExpression, deck.file + ": Blocks/" + kv.second.group};
  OwnedHorizons h;
  collectively(comm, [&] { h.value = pointHorizons(owned, ruleOf); });
  h.uniform = uniformHorizon(h.value, comm);
  for (const auto& kv : blocks) {  // the same blocks in the same order on every rank: one reduction each
    if (!kv.second.horizonExpression) continue;
    double largest = 0.0;
    for (int p = 0; p < owned.size(); ++p)
      if (owned.block[p] == kv.first) largest = std::max(largest, h.value[p]);
    h.largestOf[kv.first] = comm.max(largest);
  }
  if (deck.discretization.boxNeighbourhood && !h.largestOf.empty())
    throw InputError(deck.file + ": Blocks/" + blocks.at(h.largestOf.begin()->first).group + ": 'Horizon' is an "
                     "expression in x, y, z; PdQuickGrid's box neighbourhood takes one horizon");
  return h;
}

// Collective. Per overlap node (the layout's order, ghosts imported), each point's own horizon; empty when one value
// holds everywhere (FamilyView::pointHorizon stays null: the constant path).
std::vector<double> overlapHorizons(const DistributedLayout& layout, const PointCloud& owned, const OwnedHorizons& h) {
  if (h.uniform) return {};
  std::unordered_map<int, int> ownedIndex;
  for (int p = 0; p < owned.size(); ++p) ownedIndex[owned.gid[p]] = p;
  std::vector<double> mine(layout.numOwned()), overlap(layout.numOverlap(), 0.0);
  for (int i = 0; i < layout.numOwned(); ++i) mine[i] = h.value[ownedIndex.at(layout.gids()[i])];
  layout.importToOverlap(mine.data(), overlap.data(), 1);
  return overlap;
}

}  // namespace

Problem buildProblem(const Deck& deck, const Communicator& comm) {
  Problem pb;
  const std::string& inputFile = deck.file;
  PointCloud slab = buildSlab(deck.discretization, inputFile, comm);
  requireHorizonsReachNeighbours(deck, slab);
  const std::map<int, BlockSpec> blocks = blockSpecs(deck, blockIdsOf(slab, comm));

  requireBlocksAndDimension(deck, slab, blocks, comm);
  requireEqualHorizonsForGatherForms(blocks, inputFile);

  // The slab goes to its partition owners; from here on a rank holds its own points and their ghosts only.
  PointCloud owned;
  {
    std::vector<int> index(slab.size());
    std::iota(index.begin(), index.end(), 0);
    owned = exchangePoints(comm, slab, index, partitionRcb(slab, comm));
  }
  pb.cloud = withoutPoints(slab);
  slab = PointCloud();
  const PointCloud& cloud = pb.cloud;
  const OwnedHorizons horizon = ownedHorizons(deck, blocks, owned, comm);
  // A PdQuickGrid cloud is block 1 only: its horizon sets the box neighbourhood.
  const double h1 = blocks.count(1) ? blocks.at(1).horizon : blocks.begin()->second.horizon;
  const std::array<double, 3> box = quickGridBox(deck.discretization, h1);
  BondRules rules;
  rules.cell = cloud.partialVolume ? &cloud.cell : nullptr;
  rules.box = deck.discretization.boxNeighbourhood ? &box : nullptr;
  rules.omitBondsBetweenBlocks = deck.discretization.omitBondsBetweenBlocks;
  rules.filters = &deck.discretization.bondFilters;
  auto layout = std::make_unique<DistributedLayout>(comm, owned, horizon.value, cloud.influence, rules);
  std::vector<double> x = layout->releaseCoordinates(), volume = layout->releaseVolumes();
  requireDistinctPoints(*layout, x, volume, cloud.spacing, inputFile);
  const std::vector<int>& gids = layout->gids();
  std::vector<BlockModel> blockModels;
  std::vector<double> pointHorizon = overlapHorizons(*layout, owned, horizon);
  for (const BlockRange& r : layout->blocks()) {
    const BlockSpec& s = blocks.at(r.blockId);
    const double blockHorizon = s.horizonExpression ? horizon.largestOf.at(r.blockId) : s.horizon;
    blockModels.push_back(
        BlockModel{r.blockId, s.name, s.materialName, blockHorizon, r.begin, r.end, s.material, s.criticalStretch,
                   s.ndoBand, s.tensileStrength, s.fieldOperators, s.stretchOfTime, s.initialBreaks});
    blockModels.back().bulkModulus = s.bulkModulus;
    const MaterialInput& mv = deck.material(s.materialName).values;
    // The OSB solids' `Surface Correction` (materials/SolidParameters.hpp): their influence, before m is computed.
    if (mv.has("Surface Correction") && mv.text("Surface Correction") == "Position Aware")
      positionAwareInfluence(layout->family(), r.begin, r.end, x.data(), volume.data(), isPlanar(s.material->dimension()));
  }
  const int numOwned = layout->numOwned();
  std::unordered_map<int, int> localOf;
  for (int i = 0; i < numOwned; ++i) localOf[gids[i]] = i;
  pb.model = std::make_unique<Model>(std::move(layout), std::move(x), std::move(volume), std::move(blockModels),
                                     std::move(pointHorizon));
  warnPointsWithoutBonds(*pb.model, inputFile);

  // Node sets (the owned points' gids in each) and boundary conditions.
  CloudReductions reduce;
  reduce.sum = [&](double v) { return comm.sum(v); };
  reduce.max = [&](double v) { return comm.max(v); };
  pb.nodeSets = resolveNodeSets(deck.nodeSets, owned, inputFile, reduce);
  // A block with a term on Temperature (conduction, heat capacity, plastic heating) gives the model its Temperature
  // field and that field's rate output.
  if (pb.model->hasFieldTerms("Temperature")) {
    pb.model->addField("Temperature");
    pb.model->fields().addRate("Temperature", "Flux_Divergence", pb.model->state(), pb.model->numOwned(),
                               pb.model->layout().family().numBonds());
  }
  addConditions(deck, pb, localOf, cloud.spacing);
  addLoadedField(deck, *pb.model, inputFile);
  pb.model->requireFieldsRead(inputFile);
  addRigidWalls(deck, pb, localOf);
  std::map<int, double> horizonOf;
  for (const auto& kv : blocks) horizonOf[kv.first] = kv.second.horizon;
  addContact(deck, horizonOf, *pb.model);
  return pb;
}

}  // namespace pf
