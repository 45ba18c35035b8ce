#pragma once
// The bond-associated correspondence solids (Chen & Spencer 2019): Peridigm's "Elastic Bond Associated
// Correspondence" (Peridigm_BondAssociatedCorrespondenceMaterial.cpp, Peridigm_ElasticBondAssociatedCorrespondence-
// Material.cpp) and, with the same kinematics, the J2 and viscoplastic laws of the standard correspondence models
// ("Elastic Plastic", "Isotropic Hardening", "Viscoplastic", "Drucker Prager Bond Associated Correspondence"; Peridigm
// has no plastic bond-associated model). Each bond has its own deformation gradient F_b (the mean of both ends' node gradients
// corrected along the bond, BondAssociatedKinematics.hpp), its own Flanagan-Taylor polar update and its own stress
// update (BondStressLaw.hpp); the force state takes the bond's Piola stress and the node's stress integral, with no
// hourglass term.
// Stored per bond (history, committed + trial): V_b (9), R_b (9) and the unrotated Cauchy stress (6): 48 doubles,
// 384 bytes per bond; the plastic laws add the bond's equivalent plastic strain (xi for Drucker-Prager) (2 doubles, 16 bytes). Per node:
// Peridigm's node-level F, R, V, d, stress outputs (the node's own update with the same law, outputs only).
// Order 1 gradients only; 3D only; no damage. The force is two-phase (a row of F, F-dot dt, K^-1, w0 per node).
#include <memory>

#include "BondStressLaw.hpp"
#include "core/ElasticModuli.hpp"
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "core/Tensor3.hpp"

namespace pf {

class BondAssociatedCorrespondenceMaterial : public Material {
 public:
  enum class Law { Elastic, PerfectPlastic, IsotropicHardening, Viscoplastic, DruckerPrager };
  BondAssociatedCorrespondenceMaterial(const MaterialInput& in, Law law);
  static MaterialEntry elasticEntry();
  static MaterialEntry perfectPlasticEntry();
  static MaterialEntry hardeningEntry();
  static MaterialEntry viscoplasticEntry();
  static MaterialEntry druckerPragerEntry();

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
  static void addBondForces(const FamilyView& fam, int i, const std::vector<Mat3>& P, const Mat3& S, const Mat3& Kinv,
                            double w0, double* force);

  const char* model_;
  ElasticModuli moduli_;
  std::unique_ptr<BondStressLaw> law_;
  double density_;
  mutable bool rateWanted_ = false, cauchyWanted_ = false, storedWanted_ = false, dissipatedWanted_ = false;
};

}  // namespace pf
