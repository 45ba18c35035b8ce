#pragma once
// Base of the correspondence models (Foster, Silling & Chen 2010; Peridigm's CorrespondenceMaterial): per
// owned node, K and F from its own family, the Flanagan-Taylor rotation, the model's stress update on the
// unrotated Cauchy stress, P = J sigma F^-T, T<xi> = omega P K^-1 xi and the hourglass force. In a model run
// the force is summed in gather form after the core's exchange of per-node rows; one-pass (scatter) without.
#include <string>
#include <vector>

#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "CorrespondenceKinematics.hpp"
#include "core/ElasticModuli.hpp"
#include "core/Tensor3.hpp"

namespace pf {

class CorrespondenceMaterial : public Material {
 public:
  // Reads Density, two elastic constants, Plane Strain / Thickness and Hourglass Coefficient; model names errors.
  CorrespondenceMaterial(const MaterialInput& in, const std::string& model);

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  // Gather form when the core provides FamilyView::exchange (Material::exchangeWidth): each owned node
  // sums its own force from the rows A = P K^-1, F, c of its neighbours, so np 1 and np 2 give the same bits.
  // Surface Correction = NDO Band (Li & Geng 2024, Eqs. 29-32): the rows also carry P, and band nodes take
  // the divergence form (addBandForce).
  int exchangeWidth(const FamilyView& fam) const override;
  void completeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  bool supportsSurfaceBand() const override { return true; }
  // Peridigm's correspondence kernels take each point's own horizon (correspondence.cxx: the hourglass constant).
  bool takesPointHorizon() const override { return true; }
  // Maximum Principal Stress damage (core/StressDamage.hpp), in the gather form only (a model run): each row
  // carries its point's sigma1, completeForce decides the bonds and leaves the broken ones out.
  bool breaksBondsByStress() const override { return true; }
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  void enableOutput(const std::string& name) const override;
  bool wantsCommittedPositions() const override { return storedWanted_; }  // the hourglass work
  // The end-of-step rate takes Peridigm's velocity-state gradient where the solver gives velocities (Verlet).
  bool wantsVelocity() const override { return endOfStep_; }
  // With a Thermal Expansion Coefficient alpha: Temperature_Change (the thermal strain increment leaves d before the
  // stress update, thermalIncrement).
  std::vector<std::string> fieldsRead() const override;
  double density() const override { return density_; }
  Dimension dimension() const override { return dim_; }

  const ElasticModuli& moduli() const { return moduli_; }
  // The hourglass force's c (CorrespondenceKinematics.hpp): Hourglass Coefficient times the micromodulus
  // of the bond-based solid with this bulk modulus, 18 K/(pi delta^4) in 3D (Peridigm) and, in plane
  // strain, 12 K2/(pi h delta^3) with K2 = K + mu/3 the in-plane bulk modulus (the 2D PMB solid).
  double hourglassConstant(double horizon) const;
  double micromodulus(double horizon) const;  // the same without the coefficient

  // Which rate of deformation drives the stress update ('Rate Of Deformation'): Peridigm's, at the step's end
  // (first-order polar update, peridigmPolarUpdate), or Periforge's midpoint one (flanaganTaylor).
  enum class RateRule { EndOfStep, Midpoint };
  // The parameters every correspondence model takes (the model's own ones are appended by the caller), with the
  // model's default rate rule: Peridigm's models EndOfStep (its decks' answer), Periforge's own Midpoint.
  static std::vector<ParameterSpec> commonParameters(RateRule byDefault);
  // Its terms on Temperature from those parameters (conduction, plastic heating: SolidParameters' heatTermsOf).
  static std::vector<std::unique_ptr<FieldOperator>> heatTerms(const MaterialInput& in, const std::string& model);
  // Output names of the base fields: Unrotated_Cauchy_Stress{XX,YY,ZZ,XY,YZ,XZ}, Von_Mises_Stress,
  // Deformation_Gradient{XX,...,ZZ}, Stored_Elastic_Energy, Dissipated_Energy (J per node, computed only when
  // an output asks for them: Global_Strain_Energy, Global_Dissipated_Energy; docs/materials.md, "Energy").
  static std::vector<std::string> commonOutputs();

 protected:
  // The constitutive update of the owned nodes [fam.begin, fam.end), in the unrotated frame: from the
  // committed stress tauN[k] and the unrotated strain increment de[k] = d dt[k] (k = i - fam.begin; dt[k] the time
  // since the node's last commit) to tau[k]. Reads and writes the model's own state; may throw ConstitutiveFailure.
  virtual void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                            const std::vector<Mat3>& de, const std::vector<double>& dt,
                            std::vector<Mat3>& tau) const = 0;
  virtual std::vector<StateSpec> modelStateSpecs() const { return {}; }

  // Hooke's law on an increment: lambda tr(de) I + 2 mu de = K tr(de) I + 2 mu dev(de).
  Mat3 elasticIncrement(const Mat3& de) const;

  // The energy hooks, for a model whose elastic part is not the isotropic Hooke law of these moduli (the
  // defaults are right for every model that uses elasticIncrement): the stored elastic energy per unit
  // (current) volume of the unrotated stress tau, 1/2 tau : C^-1 : tau, and the elastic strain of a stress
  // increment, C^-1 : dtau. The plastic work increment per volume is then tau_mid : (de - C^-1 : dtau).
  virtual double elasticEnergyDensity(const Mat3& tau) const;
  virtual Mat3 elasticStrain(const Mat3& dtau) const;

 private:
  // Per owned node, the time since its last commit (Correspondence_Time; FamilyView::startTime before any), and
  // the trial time set to FamilyView::time.
  std::vector<double> stepLengths(const FamilyView& fam, StateStore& state) const;

  ElasticModuli moduli_;
  double thickness_ = 0.0;  // before dim_: its initialiser writes it
  Dimension dim_;
  double density_;
  double hourglass_;  // Hourglass Coefficient
  double alpha_ = 0.0;  // Thermal Expansion Coefficient; 0: none
  bool endOfStep_;      // 'Rate Of Deformation' = 'End Of Step'
  // de -= the increment of the thermal stretch F_th = (1 + alpha dT) I off every diagonal component (zz too: in
  // plane strain the out-of-plane strain is held, so its thermal part is a mechanical strain). Midpoint: in the
  // midpoint form the kinematics use for d (flanaganTaylor: d = (F - F_n) F_mid^-1), alpha (dT - dT_n) / (1 + alpha
  // (dT + dT_n) / 2), so that (1 + alpha dT) I is exactly stress-free; end of step: Peridigm's alpha (dT - dT_n)
  // (elastic_correspondence.cxx, updateElasticCauchyStress), stress-free for a stretch growing as
  // lambda_n / (1 - alpha (dT - dT_n)) per step.
  void subtractThermalIncrement(const FamilyView& fam, const StateStore& state, std::vector<Mat3>& de) const;
  // Set by enableOutput before the run (blocks share the material): the energy fields cost a little per node
  // and bond, so only runs that ask for them pay; they never change a force.
  mutable bool storedWanted_ = false, dissipatedWanted_ = false;
  // Peridigm's tensor and vector outputs beyond the state the update needs (docs/output.md), in
  // CorrespondenceOutputs.cpp: each computed only when an output asks (enableTensorOutput), none changes a force.
  // Unrotated_Rate_Of_Deformation = d dt / dt with dt the time since this node's last commit
  // (Correspondence_Time; a step of zero length keeps the committed rate); Cauchy_Stress = R tau R^T;
  // Hourglass_Force_Density{X,Y,Z}: the hourglass part of the force density (completeForce).
  std::vector<StateSpec> outputStateSpecs() const;
  // subtractThermalIncrement and updateStress, with the rate and Cauchy stress outputs around them.
  void stressUpdate(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& R, const std::vector<double>& dt,
                    const std::vector<Mat3>& tauN, std::vector<Mat3>& de, std::vector<Mat3>& tau) const;
  void enableTensorOutput(const std::string& name) const;
  void writeRateOfDeformation(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& de,
                              const std::vector<double>& dt) const;
  void writeCauchyStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& R,
                         const std::vector<Mat3>& tau) const;
  // The trial arrays of Hourglass_Force_Density{X,Y,Z}, or three nulls when not asked for.
  void hourglassFields(StateStore& state, double* out[3]) const;
  mutable bool rateWanted_ = false, cauchyWanted_ = false, hourglassWanted_ = false;
};

}  // namespace pf
