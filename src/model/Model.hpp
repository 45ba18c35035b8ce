#pragma once
// The discrete peridynamic body a solver drives: owned degrees of freedom, internal force density from
// the blocks' materials, lumped density, stiffness bound, boundary conditions and state commit/rollback.
// Solvers see only this class (and never which material sits behind it).
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "parallel/DistributedLayout.hpp"
#include "core/FieldOperator.hpp"
#include "core/ForceTerm.hpp"
#include "core/Material.hpp"
#include "core/StateStore.hpp"
#include "model/FieldSet.hpp"
#include "model/NodalLoad.hpp"
#include "model/RigidWall.hpp"
#include "model/SurfaceBand.hpp"

namespace pf {

class Expression;

// One block's share of the body: its material applies to owned nodes [begin, end).
struct BlockModel {
  int blockId = 0;
  std::string name;          // "block_1"
  std::string materialName;  // sub-list name in Materials
  double horizon = 0;
  int begin = 0, end = 0;
  std::shared_ptr<const Material> material;
  double criticalStretch = 0.0;  // the block's Critical Stretch damage model; 0: no damage model (nothing breaks)
  bool surfaceBand = false;      // Surface Correction = NDO Band (model/SurfaceBand.hpp)
  double tensileStrength = 0.0;  // the block's Maximum Principal Stress damage model (f_t); 0: not that model
  std::vector<std::shared_ptr<const FieldOperator>> fieldOperators = {};  // its terms on fields (conduction, heating)
  // Time Dependent Critical Stretch: s_c(t) at the evaluated time replaces criticalStretch; null: not that model.
  std::shared_ptr<const Expression> stretchOfTime = nullptr;
  // Initial Damage: the bonds of the block's nodes that cross these start broken (criticalStretch is infinite).
  std::shared_ptr<const BondFilters> initialBreaks = nullptr;
  double bulkModulus = 0.0;  // K of its material (Peridigm's critical time step); 0: the material has no moduli
  bool damaged() const { return criticalStretch > 0.0 || tensileStrength > 0.0 || stretchOfTime != nullptr; }
};


class Model;

// Collective: throws InputError naming the load's condition (its expression context) and where it failed
// if its value at t is not finite at any of its nodes on any rank.
void requireFiniteLoad(const Model& model, const NodalLoad& load, double t);

class Model {
 public:
  // pointHorizon: per overlap node, its own horizon (model/PointHorizons.hpp) when the body's horizons differ; empty
  // when every point has its block's one horizon, the same everywhere (FamilyView::pointHorizon stays null).
  Model(std::unique_ptr<DistributedLayout> layout, std::vector<double> overlapCoords, std::vector<double> overlapVolume,
        std::vector<BlockModel> blocks, std::vector<double> pointHorizon = {});

  const DistributedLayout& layout() const { return *layout_; }
  int numOwned() const { return layout_->numOwned(); }
  int numDofs() const { return 3 * numOwned(); }

  // Internal force density f (3 per owned node) for displacements u (3 per owned node). Computes the
  // materials' trial state. Throws ConstitutiveFailure on every rank if a material cannot update on any.
  void internalForce(const double* u, double* f);
  // The same at given current positions y (3 per owned node) instead of x + u: for an integrator whose
  // positions are rounded otherwise (Peridigm's Verlet forms y = (x + u_n) + dt v, not x + u_n+1).
  void internalForceAt(const double* y, double* f);
  // The exact tangent, if every material has one (hasExactTangent). lineariseAt keeps each block's tangent at
  // displacements u (Material::makeLinearisation; a block without one is differentiated at u on each product) and
  // returns false on every rank if a material cannot linearise at u on any (collective). forceDerivative: df =
  // (d f / d u) du at the u of the last lineariseAt; false where a material's derivative fails.
  bool lineariseAt(const double* u);
  bool forceDerivative(const double* du, double* df);
  std::size_t linearisationBytes() const;  // what the kept tangents hold on this rank
  bool hasExactTangent() const;
  // commit() also keeps the evaluated positions as FamilyView::yN when a material wants them.
  void commit();
  void rollback() { state_.rollback(); }

  const std::vector<double>& density() const { return density_; }         // per owned node
  const std::vector<double>& stiffnessBound() const { return bound_; }    // per owned node
  const std::vector<double>& volume() const { return volume_; }            // per overlap node
  const std::vector<double>& coordinates() const { return x_; }            // per overlap node
  const std::vector<double>& weightedVolume() const { return m_; }         // per overlap node
  double horizonOf(int i, const BlockModel& b) const { return pointHorizon_.empty() ? b.horizon : pointHorizon_[i]; }
  const std::vector<BlockModel>& blocks() const { return blocks_; }
  // Per bond of the owned nodes: the materials' pair stiffness c_b (see Material::pairStiffness).
  std::vector<double> pairStiffness() const;
  StateStore& state() { return state_; }
  // Whether some block has a damage model: then the state has "Bond_Damage" (per bond, history: 1 broken,
  // 0 intact; committed and rolled back with the step), "Broken_Bonds" (per node, history: how many) and
  // "Damage" (per node, Peridigm's output).
  bool hasDamage() const { return hasDamage_; }

  // Quasi-static break rounds (solvers/BreakRounds.hpp; docs/input.md, "Damage Models"). Between
  // beginBreakRounds and endBreakRounds the kernels take their flags from a base set (the committed one at
  // first) instead of the committed one: setBreaking(false) keeps exactly the base broken (no new break, for
  // the iterations of a solve), setBreaking(true) adds the bonds stretched past s_c or stressed past f_t (the
  // check at a converged state); adoptBreaks makes the last evaluation's trial flags the base and returns how many bonds that added
  // (collective). No-ops without damage.
  void beginBreakRounds();
  void setBreaking(bool on) { breaking_ = on; }
  double adoptBreaks();
  void endBreakRounds() { rounds_ = false; }

  // Loading-balance correction (solvers/YieldRounds.hpp; Li & Geng, seed 003, Sec. 4.1; model/YieldRounds.cpp).
  // Between beginYieldRounds and endYieldRounds only admitted points may return-map (FamilyView::admitted); the
  // set starts empty: every point elastic, as the paper's balance module starts each load step. admitYielding(tol)
  // admits the owned points whose last evaluation left Yield_Function > tol outside the set and returns how many
  // (collective). yieldRoundsRefusal(): empty if every block's material supports the rounds
  // (Material::supportsYieldRounds), else "block 'NAME': material 'M'" of the first that does not.
  // beginYieldRounds(onSurfaceTol >= 0): the set starts instead with the points whose committed Yield_Function is
  // at least -onSurfaceTol (on their yield surface at the last commit: those that flowed in the last step).
  std::string yieldRoundsRefusal() const;
  void beginYieldRounds(double onSurfaceTol = -1.0);
  double admitYielding(double tol);
  void endYieldRounds() { yieldRounds_ = false; }

  // Collective: per owned node (9 values each, row-major), the approximate deformation gradient F at displacements u
  // (3 per owned node) and the shape tensor's inverse K^-1, from every bond of its family (Foster et al. 2010 Eqs.
  // 10, 13; core/ShapeTensor.hpp) for any material: Peridigm's compute class Deformation_Gradient, which the output
  // layer runs only at the steps it writes. Throws InputError naming the point if a family's K is singular.
  void kinematicTensors(const double* u, double* F, double* Kinv);

  int numNeighbors(int i) const { return layout_->family().offsets[i + 1] - layout_->family().offsets[i]; }

  // Boundary conditions
  // atInitialTime false (Peridigm's): applyPrescribed(t, u, true), a solver's initial state, leaves it alone.
  void addPrescribedDisplacement(NodalLoad load, bool atInitialTime = true);
  void addBodyForce(NodalLoad load);
  // One component of a follower Pressure (model/PressureLoad.hpp): value times factor at time t is that node's
  // reference traction over the layer thickness, which the NDO band turns with F (FamilyView::followerLoad). Part
  // of internalForce, not of bodyForce.
  void addFollowerPressure(NodalLoad load);
  // Sets prescribed components of u at time t, and makes t the time of the following force evaluations
  // (FamilyView::time; the first t of the run is FamilyView::startTime). Every solver imposes the boundary
  // conditions of the time it evaluates, sub-steps included, so rate-dependent materials get the time
  // without any solver knowing about them.
  // initialState: the solver's start (not a resumed one), where only the conditions with atInitialTime are set:
  // Peridigm applies a prescribed displacement as increments from the first step on (docs/input.md).
  void applyPrescribed(double t, double* u, bool initialState = false) const;
  // Peridigm's increments for the Prescribed Displacements without atInitialTime (DirichletIncrementBC): from the
  // start state u0 at the run's first time t0 (initial conditions; a restart recomputes them from the deck), the
  // value at t is u0 + f(t) - f(t0) while f(t) differs from f(t0), else f(t) (Peridigm sets the value where an
  // increment is zero). Without this call (one-point drivers, tests) the value is f(t).
  void setPrescribedBaseline(double t0, const double* u0);
  void bodyForce(double t, double* b) const;          // b = body force density at t (zero elsewhere)
  const std::vector<char>& prescribedMask() const { return prescribed_; }  // 3 per owned node
  bool hasBodyForce() const { return !bodyForces_.empty(); }
  // Whether any condition moves the body: a prescribed displacement, a body force or a follower pressure.
  bool hasConditions() const { return !prescribedLoads_.empty() || !bodyForces_.empty() || !followerLoads_.empty(); }
  // Collective: throws InputError naming the condition if a prescribed displacement or body force is not
  // finite at t at any of its nodes. Called at the start time, before each quasi-static load step and
  // when a solver finds its state non-finite; applyPrescribed and bodyForce themselves stay unchecked.
  void requireFiniteLoads(double t) const;

  // Rigid walls (model/RigidWall.hpp): Verlet enforces them after each position update (before the
  // prescribed displacements, which win on the components they fix).
  // The first wall adds the node history field Rigid_Wall_Energy_Loss (J per node: the kinetic energy the
  // walls have removed from it so far; Global_Wall_Energy_Loss sums it), so that checkpoints carry it.
  void addRigidWall(RigidWall wall);
  const std::vector<RigidWall>& rigidWalls() const { return walls_; }
  // a: the acceleration of the step's first half kick (3 per owned node), for the walls' energy loss.
  void enforceRigidWalls(double dt, double* u, double* v, const double* a);
  // A restart: u (3 per owned node) is the committed state (FamilyView::yN of the next evaluation). Collective.
  void setCommittedDisplacement(const double* u);
  // The velocities of the state the next evaluations are at (3 per owned node; Peridigm's velocity at NP1), ghosted
  // for the materials that read FamilyView::velocity (Material::wantsVelocity); null: none from now on (a solver
  // without velocities, or the end of the one that set them). Collective unless null.
  void setVelocity(const double* v);
  // 3 per wall: this rank's share of each wall's force on the body in the last enforced step (0 before).
  const std::vector<double>& wallReactions() const { return wallReaction_; }

  // Force terms besides the materials (core/ForceTerm.hpp: contact), added by the model builder. termForce: their
  // sum (3 per owned node, overwritten) at step `step`, time t, deformed positions y and velocities v; collective.
  // termOutput: the force density a term gave at the last termForce, by its output name, or null.
  void addForceTerm(std::unique_ptr<ForceTerm> term);
  bool hasForceTerms() const { return !forceTerms_.empty(); }
  void termForce(long step, double t, const double* y, const double* v, double* f);
  const std::vector<double>* termOutput(const std::string& name) const;
  // At the last termForce, over this rank's owned points: the energy the terms store (J), and the terms' own
  // history columns (names the same on every rank) with this rank's shares of their values (to be summed).
  double termEnergy() const;
  std::vector<std::string> termHistoryNames() const;
  std::vector<double> termHistoryShares() const;
  std::string termWorkSummary() const;  // collective: each term's ForceTerm::workSummary, joined

  // The nodal fields beside the displacement (model/FieldSet.hpp): addField declares one (its state joins
  // state()); every force evaluation first imposes its conditions of the evaluated time and ghosts it, and each
  // block's view carries its values (FamilyView::fields). requireFieldsRead: InputError naming the first block
  // whose material reads a field this model does not hold (Material::fieldsRead); collective verdict.
  void addField(const std::string& name);
  FieldSet& fields() { return fields_; }
  const FieldSet& fields() const { return fields_; }
  void requireFieldsRead(const std::string& inputFile) const;
  // What every force evaluation does first, for a solver that advances a field without evaluating forces: the
  // fields' conditions at the time of the last applyPrescribed imposed on their trial values, then ghosted.
  void updateFields() { imposeFields(); }
  // The load the fields put on the body at the time of the last evaluation: |f V| over every dof of the internal
  // force at u = 0 of the blocks whose materials read a field (the force a uniform heating would make in the
  // reference configuration, i.e. what a clamped body's supports would carry). 0 without such blocks, so the
  // quasi-static solvers' load scale (LoadStepping.hpp) is unchanged for mechanics-only decks. Collective value.
  // Computed (an extra evaluation at each new time) only after requestFieldLoad(): the load-stepping solvers ask,
  // an explicit run does not pay for it.
  double fieldLoad() const { return fieldLoad_; }
  void requestFieldLoad() { fieldLoadWanted_ = true; }
  // The blocks' field operators (core/FieldOperator.hpp) on `field`: rate (per owned node) = their sum at the owned
  // values `owned` (ghosted here; collective); diagonal: the sum of |dL_i/du_i|. hasOperator: whether any block on
  // any rank has one (collective).
  void fieldRate(const std::string& field, const double* owned, double* rate);
  void fieldDiagonal(const std::string& field, double* diag) const;
  // Per owned node: the capacity per volume (rho c) of its block's terms on `field`, 0 where it has none.
  void fieldCapacity(const std::string& field, double* capacity) const;
  // Collective: whether every point (on every rank) has a capacity on `field` (> 0), the field existing.
  bool capacityEverywhere(const std::string& field) const;
  // Per owned node: the blocks' sources on `field` (W/m^3 for Temperature) over the last evaluated step of length dt
  // (the trial state less the committed one: call between internalForce and commit).
  void fieldSource(const std::string& field, double dt, double* source) const;
  // Per owned node: the field's surface conditions' source at the time of the last applyPrescribed (Heat Flux
  // q / l, Convection h T_amb / l; model/FieldSurface.hpp); their linear part is in fieldRate and fieldDiagonal.
  void fieldSurfaceSource(const std::string& field, double* source) const;
  // Collective: whether some block has a linear operator (conduction, or a convection condition) / a source (plastic
  // heating, or a surface condition) / any term on it.
  bool hasOperator(const std::string& field) const;
  bool hasFieldSource(const std::string& field) const;
  bool hasFieldTerms(const std::string& field) const;
  // Whether any block on any rank has a force model (Material::hasForceModel); collective.
  bool hasForceModel() const;

  // The NDO surface band's geometry (outer normals per owned node), or null when no block has the band.
  const SurfaceBand* surfaceBand() const { return band_.get(); }

  double sum(double v) const { return layout_->sum(v); }
  double max(double v) const { return layout_->max(v); }

 private:
  std::unique_ptr<DistributedLayout> layout_;
  std::vector<double> x_, volume_, m_, density_, bound_;
  std::vector<double> pointHorizon_;  // per overlap node; empty: one horizon everywhere
  std::vector<BlockModel> blocks_;
  StateStore state_;
  bool hasDamage_ = false;
  bool rounds_ = false, breaking_ = true;      // break rounds: active, new breaks allowed
  std::vector<double> baseBroken_, baseCount_;  // the base set of the rounds (per bond, per owned node)
  bool yieldRounds_ = false;                    // loading-balance rounds active
  std::vector<char> admitted_;                  // their admitted plastic set (per owned node)
  FamilyView view(const BlockModel& b);  // the block's family, with its damage arrays if it has a model
  std::vector<double> uOverlap_, yOverlap_, fOverlap_, duOverlap_;
  std::vector<double> yLinearised_;  // overlap positions of the last lineariseAt
  std::vector<std::unique_ptr<MaterialLinearisation>> linearisations_;  // per block; null: forceDerivative per product
  std::unique_ptr<SurfaceBand> band_;             // null: no block has the NDO band
  FieldSet fields_;
  std::vector<double> fieldOverlap_;  // fieldRate's ghosted values
  // The field operators' own node values (FieldOperator::nodeValue), per overlap node, ghosted once at construction,
  // and the view of them the operators get as FamilyView::fields.
  std::map<std::string, std::vector<double>> operatorValueArrays_;
  FieldValues operatorValues_;
  void prepareFieldOperators();
  void applyInitialDamage();  // the Initial Damage blocks' cut bonds broken in both state copies
  double criticalStretchNow(const BlockModel& b) const;  // s_c(time_) of a Time Dependent Critical Stretch block
  double fieldLoad_ = 0.0, fieldLoadTime_ = NAN;
  bool fieldLoadWanted_ = false;
  void updateFieldLoad();
  bool fieldsStarted_ = false;  // their start values set (FieldSet::start), or restored by a restart
  void imposeFields();          // FieldSet::impose at time_, starting the fields first if needed
  int exchangeWidth_ = 0;                         // the widest Material::exchangeWidth of the blocks
  std::vector<double> exchange_, exchangeOwned_;  // per overlap node / owned node, exchangeWidth_ each
  void forceAtOverlapPositions(double* f);  // internalForce's evaluation once yOverlap_ holds the positions
  // The second phase of internalForce at positions y (every two-phase block, or only those reading a field).
  void exchangeAndComplete(const double* y, bool onlyFieldReaders);
  static bool readsField(const BlockModel& b);    // its material reads a field (Material::fieldsRead)
  std::vector<double> yEvaluated_, yCommitted_;  // positions of the last internalForce and of the last commit
  std::vector<double> vOverlap_;                 // setVelocity's ghosted velocities; empty: none
  int velocityWanted_ = -1;                      // some block's material reads them (on any rank); -1: not asked yet
  bool wantsPositions() const;
  std::vector<NodalLoad> prescribedLoads_, bodyForces_, followerLoads_;
  std::vector<double> followerQ_;                  // 3 per owned node at followerTime_ (FamilyView::followerLoad)
  double followerTime_ = NAN;
  void updateFollowerLoads();
  std::vector<char> prescribed_;
  std::vector<char> prescribedAtStart_;  // per prescribedLoads_ entry: also applied in the initial state
  // Per prescribedLoads_ entry, per node of the load: f(t0) and u0 - f(t0) (setPrescribedBaseline); empty: none.
  std::vector<std::vector<double>> prescribedStart_, prescribedOffset_;
  std::vector<RigidWall> walls_;
  std::vector<std::unique_ptr<ForceTerm>> forceTerms_;
  std::map<std::string, std::vector<double>> termOutputs_;  // per term's output name, 3 per owned node
  std::vector<double> wallReaction_, mass_;
  // The clock applyPrescribed sets (mutable: imposing a time's conditions is what advances it).
  mutable double time_ = 0.0, startTime_ = 0.0;
  mutable bool clockStarted_ = false;
  FamilyView referenceView(const BlockModel& b) const;  // the block's reference family: points, volumes, horizons
  FamilyView blockView(const BlockModel& b) const;      // referenceView + time, committed positions, velocity, band
};

}  // namespace pf
