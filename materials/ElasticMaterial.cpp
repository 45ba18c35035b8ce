#include "ElasticMaterial.hpp"

#include "OsbKernels.hpp"

namespace pf {

ElasticMaterial::ElasticMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), dim_(dimensionFrom(in, &thickness_)), density_(in.get("Density")),
      osb_(osbConstants(dim_, moduli_)) {}

MaterialEntry ElasticMaterial::entry() {
  return {"Elastic", "linear ordinary state-based solid", elasticSolidParameters(),
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticMaterial(in)); }};
}

std::vector<StateSpec> ElasticMaterial::stateSpecs() const {
  return {{"Dilatation", Location::Node, false, true}};
}

void ElasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                   double* force) const {
  osbElasticDilatationAndForce(fam, osb_, y, state.trial("Dilatation"), force);
}

void ElasticMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  osbStiffnessBound(fam, osb_, bound);
}

}  // namespace pf

namespace pf {
void ElasticMaterial::pairStiffness(const FamilyView& fam, double* c) const { osbPairStiffness(fam, osb_, c); }
}  // namespace pf

namespace pf {
bool ElasticMaterial::forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore&,
                                      double* dforce) const {
  osbElasticForceDerivative(fam, osb_, y, dy, dforce);
  return true;
}
}  // namespace pf
