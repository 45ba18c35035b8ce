#pragma once
// Peridigm's J2 correspondence solids on Periforge's correspondence kinematics (CorrespondenceMaterial), each with
// Peridigm's stress update in the unrotated frame (PeridigmJ2Update.hpp):
//  "Elastic Plastic Correspondence" (Peridigm_ElasticPlasticCorrespondenceMaterial.cpp): perfect plasticity, Y;
//  "Isotropic Hardening Correspondence" (Peridigm_IsotropicHardeningPlasticCorrespondenceMaterial.cpp): linear
//  isotropic hardening Y + H eps_p, with Peridigm's optional flaw: Y(x) = Y (1 - m exp(-|x - x_f|^2 / s^2)) at the
//  point's reference position x;
//  "Viscoplastic Needleman Correspondence" (Peridigm_ViscoPlasticNeedlemanCorrespondenceMaterial.cpp): Needleman's
//  rate-dependent flow stress (NeedlemanLaw), with the same flaw.
// Each writes Equivalent_Plastic_Strain (node history) besides the correspondence outputs.
#include "CorrespondenceMaterial.hpp"
#include "PeridigmJ2Update.hpp"

namespace pf {

class ElasticPlasticCorrespondenceMaterial : public CorrespondenceMaterial {
 public:
  enum class Law { Perfect, LinearHardening, Needleman };
  ElasticPlasticCorrespondenceMaterial(const MaterialInput& in, Law law);
  static MaterialEntry entry();           // "Elastic Plastic Correspondence"
  static MaterialEntry hardeningEntry();  // "Isotropic Hardening Correspondence"
  static MaterialEntry needlemanEntry();  // "Viscoplastic Needleman Correspondence"

  // The yield stress at reference position x (the flaw's reduction; Y without a flaw).
  double yieldStressAt(const double* x) const;

 protected:
  void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                    const std::vector<Mat3>& de, const std::vector<double>& dt,
                    std::vector<Mat3>& tau) const override;
  std::vector<StateSpec> modelStateSpecs() const override;

 private:
  Law law_;
  double yield_, modulus_ = 0.0;  // Y, H
  NeedlemanLaw needleman_;
  bool flaw_ = false;
  double flawAt_[3] = {0.0, 0.0, 0.0}, flawSize_ = 1.0, flawMagnitude_ = 0.0;
};

}  // namespace pf
