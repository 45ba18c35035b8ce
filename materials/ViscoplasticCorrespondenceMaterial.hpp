#pragma once
// "Viscoplastic Correspondence": Foster, Silling & Chen (2010)'s rate-dependent J2 solid (FosterViscoplasticity)
// on the correspondence kinematics (CorrespondenceMaterial). The step's dt is the evaluation time
// (FamilyView::time) minus the node's committed time, kept as node history so that restarts carry it.
// Optional thermal softening (Johnson & Cook 1983's factor): the flow stress times 1 - T*^q,
// T* = (T - T_r) / (T_m - T_r) clamped to [0, 1], T the point's Temperature at the evaluation (in a staggered
// explicit run, the step's start temperature).
#include "CorrespondenceMaterial.hpp"
#include "FosterViscoplasticity.hpp"

namespace pf {

class ViscoplasticCorrespondenceMaterial : public CorrespondenceMaterial {
 public:
  explicit ViscoplasticCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();
  const FosterLaw& law() const { return law_; }
  std::vector<std::string> fieldsRead() const override;
  // 1 - T*^q for the temperature T (1 without softening).
  double softening(double T) const;

 protected:
  void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                    const std::vector<Mat3>& de, const std::vector<double>& dt,
                    std::vector<Mat3>& tau) const override;
  std::vector<StateSpec> modelStateSpecs() const override;

 private:
  FosterLaw law_;
  bool softens_ = false;
  double melting_ = 0.0, roomTemperature_ = 0.0, softeningExponent_ = 1.0;  // T_m, T_r, q
};

}  // namespace pf
