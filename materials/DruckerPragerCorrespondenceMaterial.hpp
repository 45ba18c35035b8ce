#pragma once
// "Drucker Prager Correspondence": Li & Geng's Drucker-Prager solid with hyperbolic hardening and
// non-associated flow (seed 003, Section 4.3, Eqs. 38-48 and Appendix A1-A18; DruckerPragerPlasticity) on
// the correspondence kinematics (CorrespondenceMaterial). 3D and plane strain; no plane stress (the base
// takes no Plane Stress parameter: the out-of-plane stretch would have to come from the return itself).
// No bond damage (breaksBonds() false, as the other correspondence models): damage by stress is separate.
#include "CorrespondenceMaterial.hpp"
#include "DruckerPragerPlasticity.hpp"

namespace pf {

class DruckerPragerCorrespondenceMaterial : public CorrespondenceMaterial {
 public:
  explicit DruckerPragerCorrespondenceMaterial(const MaterialInput& in);
  static MaterialEntry entry();
  const DruckerPragerLaw& law() const { return law_; }
  // Loading-balance correction: a point not admitted keeps the elastic trial (xi unchanged); Yield_Function is
  // druckerPragerYieldRatio of the evaluated stress and m.
  bool supportsYieldRounds() const override { return true; }

 protected:
  void updateStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& tauN,
                    const std::vector<Mat3>& de, const std::vector<double>& dt,
                    std::vector<Mat3>& tau) const override;
  std::vector<StateSpec> modelStateSpecs() const override;

 private:
  DruckerPragerLaw law_;
};

}  // namespace pf
