#pragma once
// "Viscoplastic Correspondence": Foster, Silling & Chen (2010)'s rate-dependent J2 solid (FosterViscoplasticity)
// on the correspondence kinematics (CorrespondenceMaterial). The step's dt is the evaluation time
// (FamilyView::time) minus the node's committed time, kept as node history so that restarts carry it.
#include "CorrespondenceMaterial.hpp"
#include "FosterViscoplasticity.hpp"

namespace pf {

class ViscoplasticCorrespondenceMaterial : public CorrespondenceMaterial {
 public:
  explicit ViscoplasticCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();
  const FosterLaw& law() const { return law_; }

 protected:
  void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                    const std::vector<Mat3>& de, std::vector<Mat3>& tau) const override;
  std::vector<StateSpec> modelStateSpecs() const override;

 private:
  FosterLaw law_;
};

}  // namespace pf
