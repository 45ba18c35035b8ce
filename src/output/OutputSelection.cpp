// The OutputManager's choice of points and its checks of what the run computes, at set-up: probes, reactions,
// compute classes, and whether the requested variables exist on this run's materials (OutputManager.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "OutputManager.hpp"
#include "core/InputError.hpp"
#include "core/OutputFields.hpp"
#include "parallel/Collective.hpp"

namespace pf {

namespace {

// The owned-local indices of the points whose gid is in `gids` (ascending): a node set's, a probe's.
std::vector<int> ownedIndicesOf(const Model& model, const std::vector<int>& gids) {
  std::vector<int> out;
  const std::vector<int>& mine = model.layout().gids();
  for (int i = 0; i < model.numOwned(); ++i)
    if (std::binary_search(gids.begin(), gids.end(), mine[i])) out.push_back(i);
  return out;
}

// Whether a material declares `field` as a per-node state (what it computes and the output layer may write).
bool declaresNodeField(const Material& material, const std::string& field) {
  for (const StateSpec& s : material.stateSpecs())
    if (s.name == field && s.where == Location::Node) return true;
  return false;
}

}  // namespace

// Collective: the owned points a compute class covers, checked to be some points of the whole cloud.
void OutputManager::addCompute(const ComputeSpec& spec) {
  const std::string where = inputFile_ + ": Compute Class Parameters/" + spec.name;
  requireComputed(spec.variable, "Compute Class Parameters/" + spec.name + "/Variable");
  std::vector<int> points;
  if (spec.kind == ComputeSpec::Kind::BlockData) {
    for (const BlockModel& b : model_.blocks())
      if (b.blockId == spec.block)
        for (int i = b.begin; i < b.end; ++i) points.push_back(i);
    if (model_.sum(static_cast<double>(points.size())) == 0.0)
      throw InputError(where + ": 'Block' = 'block_" + std::to_string(spec.block) + "' has no points");
  } else if (spec.kind == ComputeSpec::Kind::NodeSetData) {
    points = ownedIndicesOf(model_, pb_.nodeSets.at(spec.nodeSet));  // the set: gids of owned points, ascending
  } else {
    double d2 = 0.0, at[3];
    const int id = nearestPoint(spec.at.data(), &d2, at);
    if (id < 0) throw InputError(where + ": no point is nearest to the position (a non-finite coordinate)");
    points = ownedIndicesOf(model_, {id});
  }
  computes_.add(spec, points, isCoreVectorField(spec.variable));
}

// The names are known to the input layer; whether this run's materials compute them is known here.
// Collective: a rank holds only its own blocks' materials, so the question is whether any rank's do (a
// rank-local answer stopped one rank while the others went on and waited for it). Points of a material
// without the variable write 0 (elementScalar).
void OutputManager::requireComputed(const std::string& var, const std::string& where) const {
  if (isCoreVectorField(var) || isCoreScalarField(var)) return;
  const std::vector<std::string>& fieldOutputs = fieldScalarOutputs();
  if (std::find(fieldOutputs.begin(), fieldOutputs.end(), var) != fieldOutputs.end()) {
    const std::vector<std::string> held = model_.fields().outputs();
    if (std::find(held.begin(), held.end(), var) == held.end())
      throw InputError(inputFile_ + ": " + where + ": '" + var +
                       "' needs the Temperature field: give a 'Prescribed Temperature' or 'Initial Temperature' boundary "
                       "condition");
    return;
  }
  const StateStore& state = model_.state();
  const bool here = state.has(var) && state.spec(var).output && state.spec(var).where == Location::Node;
  if (model_.layout().comm().max(here ? 1.0 : 0.0) == 0.0)
    throw InputError(inputFile_ + ": " + where + ": '" + var + "' is not computed by any material of this run");
  if (here)
    for (const BlockModel& b : model_.blocks()) b.material->enableOutput(var);
}

// A whole tensor (core/OutputFields.hpp): its 9 components become element variables. Deformation_Gradient and
// Shape_Tensor_Inverse come from the model's own computation for every block (Peridigm's compute class); the others
// must be a material's node fields, stored whole or as a symmetric tensor's 6 components.
void OutputManager::addTensor(const std::string& tensor, const std::string& where) {
  const bool kinematic = isKinematicTensor(tensor);
  if (kinematic && F_.empty()) {
    // K does not change with u: a family too thin for it (a line of points) is the deck's error, told here once
    // rather than at the first step written.
    F_.assign(9 * static_cast<std::size_t>(model_.numOwned()), 0.0), Kinv_ = F_;
    const std::vector<double> u0(static_cast<std::size_t>(model_.numDofs()), 0.0);
    try {
      model_.kinematicTensors(u0.data(), F_.data(), Kinv_.data());
    } catch (const InputError& e) {
      throw InputError(inputFile_ + ": " + where + ": '" + tensor + "': " + e.what());
    }
  }
  const std::vector<std::string>& suffixes = tensorComponentSuffixes();
  for (std::size_t c = 0; c < suffixes.size(); ++c) {
    const std::string var = tensor + suffixes[c];
    if (std::find(elementScalars_.begin(), elementScalars_.end(), var) != elementScalars_.end()) continue;
    if (kinematic)
      kinematic_[var] = {tensor == "Deformation_Gradient" ? &F_ : &Kinv_, static_cast<int>(c)};
    else
      try {
        requireComputed(storedComponent(var), where);
      } catch (const InputError&) {  // every rank throws it: the question is collective
        throw InputError(inputFile_ + ": " + where + ": '" + tensor + "' is not computed by any material of this run");
      }
    elementScalars_.push_back(var);
  }
}

// The node field that holds component var on this rank: var itself, or the transposed component of a symmetric
// tensor's 6 stored ones (Unrotated_Cauchy_StressYX is stored as Unrotated_Cauchy_StressXY); var when neither.
std::string OutputManager::storedComponent(const std::string& var) const {
  const StateStore& state = model_.state();
  if (state.has(var)) return var;
  const std::string t = transposedComponentName(var);
  return state.has(t) ? t : var;
}

// A global summed from a node field (core/OutputFields.hpp) needs that field on every node that can carry it:
// a material field from every block's material (a block without it would drop out of the sum silently).
// Collective (each rank checks its own blocks; a failure on one is every rank's error).
void OutputManager::requireGlobal(const std::string& var, const std::string& where) const {
  if (var == "Global_Contact_Energy" && !model_.hasForceTerms())  // the same model on every rank
    throw InputError(inputFile_ + ": " + where + ": '" + var + "' needs a Contact list");
  if (var == "Global_Heat") {
    // Every point needs a heat capacity: a point without one would drop out of the sum silently.
    if (!model_.capacityEverywhere("Temperature"))
      throw InputError(inputFile_ + ": " + where + ": 'Global_Heat' needs a heat capacity at every point: 'Density' "
                                                   "and 'Specific Heat Capacity' in every block's material");
    return;
  }
  const char* field = globalSourceField(var);
  if (!field) return;
  const std::string f = field;
  collectively(model_.layout().comm(), [&] {
    if (f == "Rigid_Wall_Energy_Loss") {
      if (model_.rigidWalls().empty())
        throw InputError(inputFile_ + ": " + where + ": '" + var + "' needs a Rigid Wall boundary condition");
      return;
    }
    for (const BlockModel& b : model_.blocks())
      if (!declaresNodeField(*b.material, f))
        throw InputError(inputFile_ + ": " + where + ": '" + var + "' needs '" + f + "' from every material, and material '" +
                         b.materialName + "' (" + b.name + ") does not compute it");
  });
  for (const BlockModel& b : model_.blocks()) b.material->enableOutput(f);
}

// Collective: the nearest point of the whole cloud, ties to the lowest id, so every rank picks the same one;
// -1 if none (a NaN coordinate). d2: its squared distance; at: its coordinates (every rank).
int OutputManager::nearestPoint(const double* at, double* d2, double* where) const {
  const std::vector<double>& x = model_.coordinates();
  const std::vector<int>& gids = model_.layout().gids();
  int best = -1;
  double mine = std::numeric_limits<double>::max();
  for (int i = 0; i < model_.numOwned(); ++i) {
    double d = 0;
    for (int c = 0; c < 3; ++c) d += (x[3 * i + c] - at[c]) * (x[3 * i + c] - at[c]);
    if (d < mine || (d == mine && best >= 0 && gids[i] < gids[best])) mine = d, best = i;
  }
  const Communicator& comm = model_.layout().comm();
  *d2 = -comm.max(-mine);
  const double id = -comm.max(best >= 0 && mine == *d2 ? -static_cast<double>(gids[best]) : -1e300);
  if (id == 1e300) return -1;
  const bool owner = best >= 0 && gids[best] == id;
  double mineX[3] = {0, 0, 0};
  if (owner) std::copy(&x[3 * best], &x[3 * best] + 3, mineX);
  comm.sum(mineX, where, 3);  // only the owner adds: the sum is its coordinates exactly
  return static_cast<int>(id);
}

// Collective: the grid spacing, or on an irregular cloud (Text File, unequal QuickGrid spacings) the distance
// from point q (at xq) to its nearest neighbour: how far a probe may lie from the body and still mean q.
double OutputManager::spacingAt(int q, const double* xq) const {
  if (pb_.cloud.spacing > 0.0) return pb_.cloud.spacing;
  const std::vector<double>& x = model_.coordinates();
  const std::vector<int>& gids = model_.layout().gids();
  double d2 = std::numeric_limits<double>::max();
  for (int i = 0; i < model_.numOwned(); ++i) {
    if (gids[i] == q) continue;
    double d = 0;
    for (int c = 0; c < 3; ++c) d += (x[3 * i + c] - xq[c]) * (x[3 * i + c] - xq[c]);
    d2 = std::min(d2, d);
  }
  d2 = -model_.layout().comm().max(-d2);
  return model_.layout().numGlobal() > 1 ? std::sqrt(d2) : std::numeric_limits<double>::max();
}

OutputManager::Probe OutputManager::locateProbe(const ProbeSpec& p, const std::string& listName) const {
  double d2 = 0, xb[3] = {0, 0, 0};
  const int best = nearestPoint(p.at.data(), &d2, xb);
  std::ostringstream at;
  at << "(" << p.at[0] << ", " << p.at[1] << ", " << p.at[2] << ")";
  if (best < 0)
    throw InputError(inputFile_ + ": " + listName + "/Probes/" + p.name + ": position " + at.str() + " is not a point");
  const double h = spacingAt(best, xb);
  if (std::sqrt(d2) > h * (1.0 + 1e-9)) {
    std::ostringstream msg;
    msg << inputFile_ << ": " << listName << "/Probes/" << p.name << ": position " << at.str()
        << " is outside the body: the nearest point is " << std::sqrt(d2) << " away, more than the grid spacing " << h;
    throw InputError(msg.str());
  }
  Probe probe{p.name, -1, p.variables};
  for (const std::string& var : probe.variables) requireComputed(var, listName + "/Probes/" + p.name);
  const std::vector<int> owner = ownedIndicesOf(model_, {best});
  if (!owner.empty()) probe.local = owner.front();
  if (model_.layout().rank() == 0)
    std::printf("probe %s: node %d at (%g, %g, %g)\n", p.name.c_str(), best + 1, xb[0], xb[1], xb[2]);
  return probe;
}

// "Reactions" (labelled by "Reaction Names"), or by default every node set of a Prescribed Displacement.
void OutputManager::addReactions(const OutputSpec& out) {
  const std::vector<std::string>& sets = out.reactionsGiven ? out.reactions : pb_.prescribedNodeSets;
  const std::vector<std::string>& labels = out.reactionsGiven ? out.reactionNames : pb_.prescribedNodeSets;
  for (std::size_t k = 0; k < sets.size(); ++k)  // a set: gids of owned points, ascending
    reactions_.push_back(Reaction{sets[k], labels[k], ownedIndicesOf(model_, pb_.nodeSets.at(sets[k]))});
}

// Collective: per block id of the whole cloud, which element variables its material computes (the core's are
// everyone's), so that the Exodus file leaves a variable out of the blocks that lack it, as Peridigm does. Each
// rank knows its own blocks' materials; the flags are gathered as (id, flag...) rows and or-ed.
void OutputManager::findElementVariablesOfBlocks() {
  const std::size_t n = elementScalars_.size();
  std::vector<double> mine;
  for (const BlockModel& b : model_.blocks()) {
    mine.push_back(b.blockId);
    for (const std::string& var : elementScalars_)
      mine.push_back(isCoreScalarField(var) || kinematic_.count(var) || declaresNodeField(*b.material, var) ||
                             declaresNodeField(*b.material, transposedComponentName(var))
                         ? 1.0
                         : 0.0);
  }
  const std::vector<double> all = model_.layout().comm().allGather(mine);
  elementVariablesOf_.clear();
  for (std::size_t r = 0; r + n < all.size(); r += n + 1) {
    std::vector<char>& flags = elementVariablesOf_[static_cast<int>(all[r])];
    flags.resize(n, 0);
    for (std::size_t k = 0; k < n; ++k) flags[k] = flags[k] || all[r + 1 + k] != 0.0;
  }
}

}  // namespace pf
