#pragma once
// A constitutive model: turns deformed positions of a family into force densities. It is handed plain
// arrays (FamilyView, StateStore) and knows nothing of MPI, files or solvers. One instance per block.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "BondFamily.hpp"
#include "Dimension.hpp"
#include "MaterialLinearisation.hpp"
#include "StateStore.hpp"

namespace pf {

// Thrown by computeForce when a constitutive update cannot be completed (e.g. the return mapping did
// not converge). Solvers treat it as a failed iteration of the load step, never as a result.
class ConstitutiveFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Material {
 public:
  virtual ~Material() = default;

  // Per-node and per-bond state this model needs; the core allocates it before the first call.
  virtual std::vector<StateSpec> stateSpecs() const { return {}; }

  // Adds to force (3 per overlap node, owned and ghost) the internal force density of the bonds of owned
  // nodes [fam.begin, fam.end): f_i += T_i<j> V_j and f_j -= T_i<j> V_i. y: deformed positions, 3 per
  // overlap node. Writes trial state only.
  virtual void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const = 0;

  // An upper bound on sum_j |dF_i/du_j| per owned node in [fam.begin, fam.end) (force density per
  // length): the diagonal fictitious density of adaptive dynamic relaxation and the stable time step.
  virtual void stiffnessBound(const FamilyView& fam, double* bound) const = 0;

  // The exact directional derivative of computeForce at deformed positions y along dy (3 per overlap
  // node): adds dF to dforce with the same two-ended accumulation. Reads the committed state, held fixed: a
  // history-dependent model differentiates its whole update from it at y (the J2 models: the consistent
  // tangent of the return mapping). Only called when hasForceDerivative(); models without an exact tangent
  // leave both alone and the implicit solver differentiates the residual numerically.
  virtual bool hasForceDerivative() const { return false; }
  virtual bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                               double* dforce) const {
    return false;
  }
  // The same derivative kept at one point (core/MaterialLinearisation.hpp), for a model whose derivative repeats
  // work that does not depend on dy. Null (the default): the solvers call forceDerivative per product.
  virtual std::unique_ptr<MaterialLinearisation> makeLinearisation() const { return nullptr; }

  // Per bond b of owned nodes [fam.begin, fam.end): c_b such that c_b V_j n n^T approximates the part of
  // dF_i/du_j carried by the bond's own extension (no dilatation coupling): the sparse preconditioner of
  // the implicit solver. Elastic moduli are enough; the Krylov solve applies the exact operator.
  virtual void pairStiffness(const FamilyView& fam, double* c) const = 0;

  // Called before the run for each output field of this material that an output list will write, so a
  // model can skip work for fields nobody reads (e.g. an energy pass). Default: every field is always
  // computed. const because blocks share the material; the flag it sets must not change results.
  virtual void enableOutput(const std::string& name) const {}
  // Whether computeForce wants FamilyView::yN (the committed deformed positions): the core then keeps a
  // copy of the overlap positions per commit. Default no; asked on each evaluation and commit.
  virtual bool wantsCommittedPositions() const { return false; }
  // Whether computeForce reads FamilyView::velocity (the velocities of the state evaluated, where the solver has
  // them): the core then ghosts them per evaluation. Default no.
  virtual bool wantsVelocity() const { return false; }

  // Whether computeForce honours FamilyView's bond damage (core/BondDamage.hpp). A block with a damage model
  // and a material that does not is refused at input, so no deck silently runs without its breaks.
  virtual bool breaksBonds() const { return false; }
  // Whether the model applies the Maximum Principal Stress damage model (core/StressDamage.hpp; FamilyView::
  // tensileStrength): it has a Cauchy stress per point and decides each bond from both ends' sigma1. A block with
  // that damage model and a material that returns false is refused at input.
  virtual bool breaksBondsByStress() const { return false; }

  // Loading-balance correction (Li & Geng, seed 003, Sec. 4.1; solvers/YieldRounds.hpp). True: computeForce
  // honours FamilyView::admitted (a point flagged 0 takes the elastic trial state) and writes, on every
  // evaluation, the node field "Yield_Function": the yield function of the evaluated state made dimensionless
  // by the model (docs/materials.md), > 0 exactly where the point lies outside its elastic domain. A solver
  // option that needs it is refused for a block whose material returns false.
  virtual bool supportsYieldRounds() const { return false; }

  // Two-phase evaluation, for a force summed in gather form (each owned node adds only its own force, from
  // its neighbours' per-node tensors: the same sums in the same order at any rank count). A model that
  // returns w > 0 writes w values per owned node to fam.exchange (when the core provides it) in computeForce
  // and adds no bond force there; the core imports the rows to the ghosts, then calls completeForce, which
  // adds the whole force density of the owned nodes [fam.begin, fam.end). Without fam.exchange (one-node
  // drivers, unit tests) computeForce is the one-pass evaluation above.
  virtual int exchangeWidth(const FamilyView& fam) const { return 0; }
  virtual void completeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const {}
  // More than one exchange (Peridigm's Eulerian hypoelastic correspondence: a node's gradient needs its neighbours'
  // Jacobians, a bond's needs both ends' gradients): completeForce is called once per round r (fam.exchangeRound),
  // rounds before the last rewrite the owned rows, which the core imports to the ghosts before the next round.
  virtual int exchangeRounds() const { return 1; }
  // What a row holds, for the models whose rows a neighbour reads: blocks of a body whose rows differ (a plain
  // correspondence model beside a bond-associated one) are refused, as neither could read the other's rows.
  virtual std::string exchangeLayout() const { return "correspondence"; }
  // Whether the model honours FamilyView's surface band (Surface Correction = NDO Band); a block asking for
  // it with a model that does not is refused at input.
  virtual bool supportsSurfaceBand() const { return false; }
  // Whether the model reads each point's own horizon (horizonAt(fam, i), FamilyView::pointHorizon) wherever the
  // horizon enters, as Peridigm's correspondence models do; false: one horizon per block (fam.horizon), and a
  // block whose Horizon is an expression in x, y, z is refused at input (Peridigm's other models refuse it too).
  virtual bool takesPointHorizon() const { return false; }

  // The nodal fields (core/FieldValues.hpp) computeForce reads through FamilyView::fields, e.g.
  // "Temperature_Change" for thermal expansion. A deck whose model does not hold one of them is refused at
  // input, so a material never runs without a field it was given parameters for.
  virtual std::vector<std::string> fieldsRead() const { return {}; }

  // False for a block that only carries a field operator (Peridigm's Diffusion): no force, no stiffness; a solver
  // of the displacement refuses a model none of whose blocks has a force model.
  virtual bool hasForceModel() const { return true; }

  virtual double density() const = 0;
  virtual Dimension dimension() const = 0;
};

}  // namespace pf
