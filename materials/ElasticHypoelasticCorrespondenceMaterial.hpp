#pragma once
// "Elastic Hypoelastic Correspondence": Peridigm's bond-associated, semi-Lagrangian hypoelastic correspondence solid
// (Behzadinasab & Foster; Peridigm_HypoelasticCorrespondenceMaterial.cpp, Peridigm_ElasticHypoelasticCorrespondence-
// Material.cpp, correspondence.cxx). Everything lives on the current configuration: the gradient weights
// phi = omega M^-1 Y with M = sum omega Y (x) Y J_N,j V_j on the deformed bonds Y, the velocity gradient
// L = sum (v_j - v_i) (x) phi J_N,j V_j, the Jacobian J = J_N (1 + tr L dt); each bond has its own
// L_b = Lbar + (v_j - v_i - Lbar Y) (x) Y / |Y|^2, Flanagan-Taylor rotation and stress, and the force state
// T = omega / w0 sigma_b Y / |Y|^2 + S_i phi_b (S: the nonhomogeneity integral of the bonds' Cauchy stresses).
// Stored per bond (history): V_b, R_b (9 each), the unrotated stress (6): 48 doubles, 384 bytes per bond.
// Influence function One only (Peridigm evaluates omega on the deformed bond with 'Actual Horizon', which with One
// changes nothing); order 1 gradients only; 3D; no damage. Three phases: the rows are exchanged twice.
#include "core/ElasticModuli.hpp"
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "core/Tensor3.hpp"

namespace pf {

class ElasticHypoelasticCorrespondenceMaterial : public Material {
 public:
  explicit ElasticHypoelasticCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  std::vector<StateSpec> stateSpecs() const override;
  // Phase 1 (with fam.exchange): each owned node's committed J in its row. Without it (unit tests, every node
  // owned): all three phases here on a local row buffer.
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  int exchangeWidth(const FamilyView&) const override { return kRow; }
  int exchangeRounds() const override { return 2; }
  // Round 0: weights, L, J, w0 and the node-level outputs (rows: L dt, M^-1, w0). Round 1: the bonds and the force,
  // f_i += J_i T J_j V_j, f_j -= J_j T J_i V_i (the core adds a ghost's share to its owner).
  void completeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  void enableOutput(const std::string& name) const override;
  std::string exchangeLayout() const override { return "hypoelastic"; }
  bool wantsVelocity() const override { return true; }
  bool wantsCommittedPositions() const override { return true; }  // without velocities: the step's increment
  double density() const override { return density_; }
  Dimension dimension() const override { return Dimension::ThreeD; }

  static constexpr int kRowJ = 0, kRowLdt = 1, kRowMinv = 10, kRowW0 = 19, kRowTag = 20, kRow = 21;

 private:
  void jacobianPhase(const FamilyView& fam, StateStore& state, double* rows, int stride) const;
  void nodePhase(const FamilyView& fam, const double* y, StateStore& state, double* rows, int stride) const;
  void bondPhase(const FamilyView& fam, const double* y, StateStore& state, const double* rows, int stride,
                 double* force) const;
  Mat3 elasticIncrement(const Mat3& de) const;

  ElasticModuli moduli_;
  double density_;
  mutable bool rateWanted_ = false, cauchyWanted_ = false;
};

}  // namespace pf
