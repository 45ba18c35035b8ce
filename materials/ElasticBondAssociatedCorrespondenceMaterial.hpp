#pragma once
// "Elastic Bond Associated Correspondence": Peridigm's bond-associated correspondence solid (Chen & Spencer 2019;
// Peridigm_BondAssociatedCorrespondenceMaterial.cpp, Peridigm_ElasticBondAssociatedCorrespondenceMaterial.cpp).
// Each bond has its own deformation gradient F_b (the mean of both ends' node gradients corrected along the bond,
// BondAssociatedKinematics.hpp), its own Flanagan-Taylor polar update and its own hypoelastic stress; the force
// state takes the bond's Piola stress and the node's stress integral, with no hourglass term.
// Stored per bond (history, committed + trial): V_b (9), R_b (9) and the unrotated Cauchy stress (6): 48 doubles,
// 384 bytes per bond. Per node: Peridigm's node-level F, R, V, d, stress outputs as the other correspondence models.
// Order 1 gradients only; 3D only; no damage. The force is two-phase (a row of F, F-dot dt, K^-1, w0 per node).
#include "core/ElasticModuli.hpp"
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "core/Tensor3.hpp"

namespace pf {

class ElasticBondAssociatedCorrespondenceMaterial : public Material {
 public:
  explicit ElasticBondAssociatedCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  std::vector<StateSpec> stateSpecs() const override;
  // Phase 1 with fam.exchange: the node-level kinematics and stress (outputs) and each owned node's row. Without
  // it (unit tests with every node owned): both phases here, the row buffer local.
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  int exchangeWidth(const FamilyView&) const override { return kRow; }
  // Phase 2: the bond-level update and the force of the owned nodes' bonds, f_i += T V_j, f_j -= T V_i (the core
  // adds a ghost's share to its owner). Throws ConstitutiveFailure for a bond with det F_b <= 0.
  void completeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  void enableOutput(const std::string& name) const override;
  std::string exchangeLayout() const override { return "bond-associated"; }
  bool wantsVelocity() const override { return true; }
  // Without velocities (the quasi-static solvers) F-dot dt is the step's increment from the committed positions.
  bool wantsCommittedPositions() const override { return true; }
  double density() const override { return density_; }
  Dimension dimension() const override { return Dimension::ThreeD; }

  // Row layout per node: F (9), F-dot dt (9), K^-1 (9), w0 = sum omega V_j, a tag marking a row of this model.
  static constexpr int kRowF = 0, kRowDF = 9, kRowKinv = 18, kRowW0 = 27, kRowTag = 28, kRow = 29;

 private:
  void nodePhase(const FamilyView& fam, const double* y, StateStore& state, double* rows, int stride) const;
  void bondPhase(const FamilyView& fam, const double* y, StateStore& state, const double* rows, int stride,
                 double* force) const;
  Mat3 elasticIncrement(const Mat3& de) const;  // K tr(de) I + 2 mu dev(de)

  ElasticModuli moduli_;
  double density_;
  mutable bool rateWanted_ = false, cauchyWanted_ = false;
};

}  // namespace pf
