#include "Model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Expression.hpp"
#include "core/InputError.hpp"
#include "discretization/BondCutter.hpp"
#include "parallel/Collective.hpp"

namespace pf {

Model::Model(std::unique_ptr<DistributedLayout> layout, std::vector<double> overlapCoords,
             std::vector<double> overlapVolume, std::vector<BlockModel> blocks, std::vector<double> pointHorizon)
    : layout_(std::move(layout)), x_(std::move(overlapCoords)), volume_(std::move(overlapVolume)),
      pointHorizon_(std::move(pointHorizon)), blocks_(std::move(blocks)) {
  const int n = numOwned();
  density_.assign(n, 0.0);
  bound_.assign(n, 0.0);
  std::vector<StateSpec> specs;
  // m on the overlap: kernels need a neighbour's m for the force it sends back (t_ji) and its bound.
  m_.assign(layout_->numOverlap(), 0.0);
  for (const BlockModel& b : blocks_)
    computeWeightedVolume(makeView(layout_->family(), b.begin, b.end, x_.data(), volume_.data(), m_.data(), b.horizon),
                          m_.data());
  {
    std::vector<double> owned(m_.begin(), m_.begin() + n);
    layout_->importToOverlap(owned.data(), m_.data(), 1);
  }
  bool anyBand = false;
  for (const BlockModel& b : blocks_) anyBand = anyBand || b.surfaceBand;
  if (anyBand) {
    std::vector<FamilyView> views;
    std::vector<bool> planar;
    for (const BlockModel& b : blocks_) {
      views.push_back(blockView(b));  // band_ is not set yet: the plain view
      planar.push_back(isPlanar(b.material->dimension()));
    }
    band_ = std::make_unique<SurfaceBand>(buildSurfaceBand(*layout_, views, planar));
  }
  for (const BlockModel& b : blocks_) {
    const FamilyView view = blockView(b);
    b.material->stiffnessBound(view, bound_.data());
    exchangeWidth_ = std::max(exchangeWidth_, b.material->exchangeWidth(view));
    for (int i = b.begin; i < b.end; ++i) density_[i] = b.material->density();
    for (const StateSpec& s : b.material->stateSpecs()) specs.push_back(s);
  }
  prepareFieldOperators();
  // A field term's source reads material outputs that are computed only when asked for (plastic work).
  for (const BlockModel& b : blocks_)
    for (const auto& op : b.fieldOperators)
      for (const std::string& name : op->materialOutputsRead()) b.material->enableOutput(name);
  for (const BlockModel& b : blocks_) hasDamage_ = hasDamage_ || b.damaged();
  if (hasDamage_) {
    specs.push_back({"Bond_Damage", Location::Bond, true, false});
    specs.push_back({"Broken_Bonds", Location::Node, true, false});
    specs.push_back({"Damage", Location::Node, false, true});
  }
  state_.allocate(specs, n, layout_->family().numBonds());
  if (hasDamage_) applyInitialDamage();
  const std::size_t no = static_cast<std::size_t>(layout_->numOverlap());
  uOverlap_.assign(3 * no, 0.0);
  yOverlap_.assign(3 * no, 0.0);
  fOverlap_.assign(3 * no, 0.0);
  exchange_.assign(no * exchangeWidth_, 0.0);
  exchangeOwned_.assign(static_cast<std::size_t>(n) * exchangeWidth_, 0.0);
  prescribed_.assign(3 * static_cast<std::size_t>(n), 0);
  // A planar model has no out-of-plane motion: z stays 0 and is never a free unknown of any solver.
  for (const BlockModel& b : blocks_)
    if (isPlanar(b.material->dimension()))
      for (int i = b.begin; i < b.end; ++i) prescribed_[3 * i + 2] = 1;
}

FamilyView Model::view(const BlockModel& b) {
  FamilyView v = blockView(b);
  // Each model writes the rows of its own owned nodes (blocks own disjoint node ranges).
  if (exchangeWidth_ > 0) v.exchange = exchange_.data(), v.exchangeStride = exchangeWidth_;
  if (b.damaged()) {  // else brokenN stays null: the kernels' undamaged path
    v.brokenN = rounds_ ? baseBroken_.data() : state_.committed("Bond_Damage");
    v.brokenCountN = rounds_ ? baseCount_.data() : state_.committed("Broken_Bonds");
    v.broken = state_.trial("Bond_Damage");
    v.damage = state_.trial("Damage");
    v.brokenCount = state_.trial("Broken_Bonds");
    // Frozen: no stretch exceeds infinity, so exactly the base set is broken.
    const bool frozen = rounds_ && !breaking_;
    if (b.criticalStretch > 0.0) v.criticalStretch = frozen ? HUGE_VAL : b.criticalStretch;
    if (b.stretchOfTime) v.criticalStretch = frozen ? HUGE_VAL : criticalStretchNow(b);
    if (b.tensileStrength > 0.0) v.tensileStrength = frozen ? HUGE_VAL : b.tensileStrength;
  }
  if (yieldRounds_) v.admitted = admitted_.data();  // else null: every point may yield
  if (!fields_.empty()) v.fields = &fields_.values();
  return v;
}

// Peridigm's Initial Damage (Peridigm_InitialDamageModel.cpp, initialize): a bond from owned point i to j that
// crosses one of the filters (x_i the segment's start, as there) is broken from the start, in the committed and
// the trial copy, and i's Damage is its share of broken bonds.
void Model::applyInitialDamage() {
  const BondFamily& fam = layout_->family();
  double* flags[2] = {state_.trial("Bond_Damage"), state_.restoreCommitted("Bond_Damage")};
  double* count[2] = {state_.trial("Broken_Bonds"), state_.restoreCommitted("Broken_Bonds")};
  double* damage = state_.trial("Damage");
  for (const BlockModel& b : blocks_) {
    if (!b.initialBreaks) continue;
    double longest = 0.0;
    for (int k = fam.offsets[b.begin]; k < fam.offsets[b.end]; ++k) longest = std::max(longest, fam.refLength[k]);
    if (!(longest > 0.0)) continue;
    const BondCutter cutter(*b.initialBreaks, x_, longest);
    for (int i = b.begin; i < b.end; ++i) {
      double broken = 0.0;
      for (int k = fam.offsets[i]; k < fam.offsets[i + 1]; ++k)
        if (cutter.cuts(&x_[3 * i], &x_[3 * fam.neighbors[k]])) {
          flags[0][k] = flags[1][k] = 1.0;
          broken += 1.0;
        }
      count[0][i] = count[1][i] = broken;
      const int nb = fam.offsets[i + 1] - fam.offsets[i];
      damage[i] = nb > 0 ? broken / nb : 0.0;
    }
  }
}

// Peridigm evaluates its Time Dependent Critical Stretch at the step's end time before each explicit step (and at
// 0 before the first evaluation); time_ is the time the solver last imposed conditions for, that same time.
double Model::criticalStretchNow(const BlockModel& b) const {
  const double sc = (*b.stretchOfTime)(0.0, 0.0, 0.0, time_);
  if (!std::isfinite(sc)) {
    const std::string why = b.stretchOfTime->whyNotFinite(0.0, 0.0, 0.0, time_);
    throw InputError(b.stretchOfTime->context() + ": not finite at t = " + std::to_string(time_) +
                     (why.empty() ? std::string() : " (" + why + ")"));
  }
  return sc;
}

void Model::beginBreakRounds() {
  if (!hasDamage_) return;
  const std::size_t nb = layout_->family().numBonds();
  const double* flags = state_.committed("Bond_Damage");
  const double* count = state_.committed("Broken_Bonds");
  baseBroken_.assign(flags, flags + nb);
  baseCount_.assign(count, count + numOwned());
  rounds_ = true;
  breaking_ = false;
}

double Model::adoptBreaks() {
  if (!hasDamage_) return 0.0;
  const std::size_t nb = layout_->family().numBonds();
  const double* flags = state_.trial("Bond_Damage");
  const double* count = state_.trial("Broken_Bonds");
  double added = 0.0;
  for (int i = 0; i < numOwned(); ++i) added += count[i] - baseCount_[i];
  baseBroken_.assign(flags, flags + nb);
  baseCount_.assign(count, count + numOwned());
  return sum(added);
}

void Model::internalForce(const double* u, double* f) {
  layout_->importToOverlap(u, uOverlap_.data(), 3);
  for (std::size_t k = 0; k < yOverlap_.size(); ++k) yOverlap_[k] = x_[k] + uOverlap_[k];
  forceAtOverlapPositions(f);
}

void Model::internalForceAt(const double* y, double* f) {
  layout_->importToOverlap(y, yOverlap_.data(), 3);  // a ghost gets its owner's position, bit for bit
  forceAtOverlapPositions(f);
}

void Model::forceAtOverlapPositions(double* f) {
  std::fill(fOverlap_.begin(), fOverlap_.end(), 0.0);
  updateFollowerLoads();
  imposeFields();
  // A material that fails on one rank (a return mapping that does not converge there) must fail on every
  // rank before the collective exportAdd, or the others wait in it forever: one allreduce per evaluation.
  collectively(layout_->comm(), [&] {
    for (const BlockModel& b : blocks_) b.material->computeForce(view(b), yOverlap_.data(), state_, fOverlap_.data());
  });
  if (exchangeWidth_ > 0) exchangeAndComplete(yOverlap_.data(), false);
  layout_->exportAdd(fOverlap_.data(), f, 3);
  if (wantsPositions()) yEvaluated_ = yOverlap_;
}

// Phase 2 of a two-phase evaluation (Material::exchangeWidth): the owned rows the models wrote go to the
// ghosts, then each model adds the force of its owned nodes. A bond-associated model updates each bond's stress
// here (it needs both ends' rows), which may fail on one rank only: agreed on collectively, as phase 1.
void Model::exchangeAndComplete(const double* y, bool onlyFieldReaders) {
  int rounds = 1;
  for (const BlockModel& b : blocks_) rounds = std::max(rounds, b.material->exchangeRounds());
  for (int r = 0; r < rounds; ++r) {
    std::copy(exchange_.begin(), exchange_.begin() + static_cast<long>(exchangeOwned_.size()), exchangeOwned_.begin());
    layout_->importToOverlap(exchangeOwned_.data(), exchange_.data(), exchangeWidth_);
    collectively(layout_->comm(), [&] {
      for (const BlockModel& b : blocks_)
        if (b.material->exchangeWidth(blockView(b)) > 0 && b.material->exchangeRounds() > r &&
            (!onlyFieldReaders || readsField(b))) {
          FamilyView v = view(b);
          v.exchangeRound = r;
          b.material->completeForce(v, y, state_, fOverlap_.data());
        }
    });
  }
}

bool Model::readsField(const BlockModel& b) { return !b.material->fieldsRead().empty(); }

bool Model::wantsPositions() const {
  for (const BlockModel& b : blocks_)
    if (b.material->wantsCommittedPositions()) return true;
  return false;
}

void Model::commit() {
  state_.commit();
  if (!fields_.empty()) fields_.afterCommit(state_);
  if (wantsPositions() && !yEvaluated_.empty()) yCommitted_ = yEvaluated_;
}

void Model::addField(const std::string& name) { fields_.add(name, state_, numOwned(), layout_->family().numBonds()); }

void Model::imposeFields() {
  if (fields_.empty()) return;
  if (!fieldsStarted_) fields_.start(startTime_, x_, state_), fieldsStarted_ = true;
  fields_.impose(time_, x_, state_, *layout_);
  if (fieldLoadWanted_ && time_ != fieldLoadTime_) updateFieldLoad();
}

// The reference configuration's force of the blocks that read a field, evaluated as internalForce does (both
// phases of a two-phase model) into fOverlap_, zeroed before and after; the trial
// state it writes (a dilatation, bond flags, a correspondence stress) is rewritten by the evaluation that follows.
void Model::updateFieldLoad() {
  fieldLoadTime_ = time_;
  bool reads = false;
  for (const BlockModel& b : blocks_) reads = reads || readsField(b);
  if (layout_->max(reads ? 1.0 : 0.0) == 0.0) return;
  std::vector<double> owned(static_cast<std::size_t>(numDofs()), 0.0);
  std::fill(fOverlap_.begin(), fOverlap_.end(), 0.0);  // updateFields() may come after another solver's evaluations
  for (const BlockModel& b : blocks_)
    if (readsField(b)) b.material->computeForce(view(b), x_.data(), state_, fOverlap_.data());
  if (exchangeWidth_ > 0) exchangeAndComplete(x_.data(), true);
  layout_->exportAdd(fOverlap_.data(), owned.data(), 3);
  std::fill(fOverlap_.begin(), fOverlap_.end(), 0.0);
  double s = 0.0;
  for (std::size_t k = 0; k < owned.size(); ++k) s += owned[k] * owned[k] * volume_[k / 3] * volume_[k / 3];
  fieldLoad_ = std::sqrt(sum(s));
}

void Model::requireFieldsRead(const std::string& inputFile) const {
  collectively(layout_->comm(), [&] {
    for (const BlockModel& b : blocks_)
      for (const std::string& f : b.material->fieldsRead()) {
        const std::string base = FieldSet::fieldOf(f);
        if (!fields_.has(base))
          throw InputError(inputFile + ": Materials/" + b.materialName + ": its material reads the field '" + base +
                           "', which this deck does not set: give it a 'Prescribed " + base + "' or 'Initial " + base +
                           "' boundary condition");
      }
  });
}

bool Model::hasForceModel() const {
  double mine = 0.0;
  for (const BlockModel& b : blocks_)
    if (b.material->hasForceModel()) mine = 1.0;
  return max(mine) > 0.0;
}

void Model::setCommittedDisplacement(const double* u) {
  fieldsStarted_ = true;  // a restart: the fields' values and start values came with the checkpoint
  layout_->importToOverlap(u, uOverlap_.data(), 3);
  yCommitted_.resize(x_.size());
  for (std::size_t k = 0; k < yCommitted_.size(); ++k) yCommitted_[k] = x_[k] + uOverlap_[k];
}

void Model::setVelocity(const double* v) {
  if (!v) return vOverlap_.clear();
  if (velocityWanted_ < 0) {
    bool wanted = false;
    for (const BlockModel& b : blocks_) wanted = wanted || b.material->wantsVelocity();
    velocityWanted_ = layout_->max(wanted ? 1.0 : 0.0) > 0.0 ? 1 : 0;
  }
  if (!velocityWanted_) return;
  vOverlap_.resize(x_.size());
  layout_->importToOverlap(v, vOverlap_.data(), 3);
}

FamilyView Model::referenceView(const BlockModel& b) const {
  FamilyView view = makeView(layout_->family(), b.begin, b.end, x_.data(), volume_.data(), m_.data(), b.horizon);
  if (!pointHorizon_.empty()) view.pointHorizon = pointHorizon_.data();
  return view;
}

FamilyView Model::blockView(const BlockModel& b) const {
  FamilyView view = referenceView(b);
  view.time = time_;
  view.startTime = startTime_;
  if (!yCommitted_.empty()) view.yN = yCommitted_.data();
  if (!vOverlap_.empty()) view.velocity = vOverlap_.data();
  if (band_ && b.surfaceBand) {
    view.band = band_->band.data();
    view.outerNormal = band_->outerNormal.data();
    view.layerThickness = band_->layerThickness.data();
    if (!followerLoads_.empty()) view.followerLoad = followerQ_.data();
  }
  return view;
}

std::vector<double> Model::pairStiffness() const {
  std::vector<double> c(layout_->family().numBonds(), 0.0);
  for (const BlockModel& b : blocks_) {
    b.material->pairStiffness(referenceView(b), c.data());
  }
  return c;
}

void Model::addPrescribedDisplacement(NodalLoad load, bool atInitialTime) {
  for (int i : load.nodes) prescribed_[3 * i + load.coordinate] = 1;
  prescribedAtStart_.push_back(atInitialTime ? 1 : 0);
  prescribedLoads_.push_back(std::move(load));
}

void Model::addBodyForce(NodalLoad load) { bodyForces_.push_back(std::move(load)); }
void Model::addFollowerPressure(NodalLoad load) {
  followerLoads_.push_back(std::move(load));
  followerQ_.assign(static_cast<std::size_t>(numDofs()), 0.0);
  followerTime_ = NAN;
}

namespace {
template <class Apply>
void evaluate(const NodalLoad& load, const std::vector<double>& x, double t, Apply apply) {
  forEachLoadValue(load, x, t, 3, apply);
}
}  // namespace

void Model::addRigidWall(RigidWall wall) {
  if (walls_.empty())
    state_.allocate({{"Rigid_Wall_Energy_Loss", Location::Node, true, false}}, numOwned(), layout_->family().numBonds());
  walls_.push_back(std::move(wall));
  wallReaction_.assign(3 * walls_.size(), 0.0);
}

void Model::enforceRigidWalls(double dt, double* u, double* v, const double* a) {
  if (mass_.empty())
    for (int i = 0; i < numOwned(); ++i) mass_.push_back(density_[i] * volume_[i]);
  // A history field's trial copy is stale after a commit (StateStore::commit): rewrite it from the committed
  // one on every wall node; the other nodes are 0 in both copies.
  double* loss = state_.trial("Rigid_Wall_Energy_Loss");
  const double* lossN = state_.committed("Rigid_Wall_Energy_Loss");
  for (const RigidWall& w : walls_)
    for (int i : w.nodes) loss[i] = lossN[i];
  pf::enforceRigidWalls(walls_, x_, mass_, dt, u, v, wallReaction_, a, loss);
}

void Model::applyPrescribed(double t, double* u, bool initialState) const {
  if (!clockStarted_) startTime_ = t, clockStarted_ = true;
  time_ = t;
  for (std::size_t i = 0; i < prescribedLoads_.size(); ++i) {
    if (initialState && !prescribedAtStart_[i]) continue;
    if (prescribedAtStart_[i] || prescribedStart_.empty()) {
      evaluate(prescribedLoads_[i], x_, t, [u](int k, double v) { u[k] = v; });
      continue;
    }
    const std::vector<double>& f0 = prescribedStart_[i];
    const std::vector<double>& offset = prescribedOffset_[i];
    std::size_t j = 0;  // the load's nodes in order, as evaluate visits them
    evaluate(prescribedLoads_[i], x_, t, [&](int k, double v) {
      u[k] = v != f0[j] ? v + offset[j] : v;
      ++j;
    });
  }
}

void Model::setPrescribedBaseline(double t0, const double* u0) {
  prescribedStart_.assign(prescribedLoads_.size(), {});
  prescribedOffset_.assign(prescribedLoads_.size(), {});
  for (std::size_t i = 0; i < prescribedLoads_.size(); ++i)
    evaluate(prescribedLoads_[i], x_, t0, [&](int k, double v) {
      prescribedStart_[i].push_back(v);
      prescribedOffset_[i].push_back(u0[k] - v);
    });
}

void Model::updateFollowerLoads() {
  if (followerLoads_.empty() || time_ == followerTime_) return;
  std::fill(followerQ_.begin(), followerQ_.end(), 0.0);
  for (const NodalLoad& l : followerLoads_) evaluate(l, x_, time_, [this](int k, double v) { followerQ_[k] += v; });
  followerTime_ = time_;
}

void Model::bodyForce(double t, double* b) const {
  std::fill(b, b + numDofs(), 0.0);
  for (const NodalLoad& l : bodyForces_) evaluate(l, x_, t, [b](int k, double v) { b[k] += v; });
}

void Model::requireFiniteLoads(double t) const {
  for (const NodalLoad& l : prescribedLoads_) requireFiniteLoad(*this, l, t);
  for (const NodalLoad& l : bodyForces_) requireFiniteLoad(*this, l, t);
  for (const NodalLoad& l : followerLoads_) requireFiniteLoad(*this, l, t);
}

void requireFiniteLoad(const Model& model, const NodalLoad& load, double t) {
  const std::vector<double>& x = model.coordinates();
  const std::vector<int>& gids = model.layout().gids();
  int bad = -1;  // the owned node with the smallest global id whose value is not finite
  double value = 0.0;
  evaluate(load, x, t, [&](int k, double v) {
    if (!std::isfinite(v) && (bad < 0 || gids[k / 3] < gids[bad])) bad = k / 3, value = v;
  });
  // Every rank must agree: the smallest failing global id over ranks (as a max of -id), its owner's data.
  const double big = 1e300;
  const double worst = model.max(bad >= 0 ? -static_cast<double>(gids[bad]) : -big);
  if (worst == -big) return;
  double in[4] = {0, 0, 0, 0}, out[4];
  if (bad >= 0 && -static_cast<double>(gids[bad]) == worst) {
    for (int d = 0; d < 3; ++d) in[d] = x[3 * bad + d];
    in[3] = std::isnan(value) ? 0.0 : (value > 0 ? 1.0 : -1.0);
  }
  model.layout().comm().sum(in, out, 4);
  char where[200];
  std::snprintf(where, sizeof where, " is %s at (x, y, z, t) = (%g, %g, %g, %g)",
                out[3] == 0 ? "nan" : (out[3] > 0 ? "inf" : "-inf"), out[0], out[1], out[2], t);
  // Every rank evaluates the same expression at the same point, so every rank names the same cause.
  const std::string why = load.value->whyNotFinite(out[0], out[1], out[2], t);
  throw InputError(load.value->context() + ": '" + load.value->text() + "'" + where + (why.empty() ? "" : ": " + why));
}

}  // namespace pf
