#pragma once
// "Elastic Correspondence": Peridigm's elastic correspondence solid. Hypoelastic, as Peridigm's: the
// unrotated Cauchy stress advances by Hooke's law on the unrotated strain increment,
// tau = tau_n + K tr(d dt) I + 2 mu dev(d dt), on the correspondence kinematics of CorrespondenceMaterial.
#include "CorrespondenceMaterial.hpp"

namespace pf {

class ElasticCorrespondenceMaterial : public CorrespondenceMaterial {
 public:
  explicit ElasticCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();

 protected:
  void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                    const std::vector<Mat3>& de, const std::vector<double>& dt,
                    std::vector<Mat3>& tau) const override;
};

}  // namespace pf
