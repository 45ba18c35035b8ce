#pragma once
// Plastic work to heat (Taylor & Quinney): the source beta dW_p / (V dt) on Temperature, W_p the block material's
// Dissipated_Energy (J per node, the plastic work it integrates; docs/materials.md, "Energy"), beta the
// Taylor-Quinney coefficient. Any material that declares Dissipated_Energy heats this way; the field's capacity is
// rho c. Adiabatic when the block has no conduction: then rho c dT V = beta dW_p per node, exactly.
#include "core/FieldOperator.hpp"

namespace pf {

class PlasticHeating : public FieldOperator {
 public:
  PlasticHeating(double beta, double capacity) : beta_(beta), capacity_(capacity) {}
  std::string field() const override { return "Temperature"; }
  bool isLinear() const override { return false; }
  double capacity() const override { return capacity_; }
  bool hasSource() const override { return true; }
  void addSource(const FamilyView& fam, const StateStore& state, double dt, double* out) const override;
  std::vector<std::string> materialOutputsRead() const override { return {"Dissipated_Energy"}; }

 private:
  double beta_, capacity_;
};

}  // namespace pf
