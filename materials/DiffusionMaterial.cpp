#include "DiffusionMaterial.hpp"

#include "HeatConduction.hpp"

namespace pf {

DiffusionMaterial::DiffusionMaterial(const MaterialInput& in) : density_(in.get("Density", 0.0)) {}

MaterialEntry DiffusionMaterial::entry() {
  using P = ParameterSpec;
  MaterialEntry e{"Diffusion",
                  "Peridigm's nonlocal heat conduction without a force model (ImplicitDiffusion)",
                  {P::real("Coefficient", "thermal conductivity k [W/(m K)] of the bond rule (docs/thermal.md)").need().positive(),
                   P::flag("Use Improved Quadrature",
                           "Peridigm's option: bond weights exact for temperature fields up to second order at every "
                           "point (Periforge's moment weights, materials/MomentQuadrature.hpp; docs/thermal.md)")
                       .byDefault("false"),
                   P::real("Density", "mass density [kg/m^3]; only for a transient solve (with Specific Heat Capacity)")
                       .positive(),
                   P::real("Specific Heat Capacity", "c [J/(kg K)]; only for a transient solve").positive()},
                  [](const MaterialInput& in) { return std::unique_ptr<Material>(new DiffusionMaterial(in)); },
                  {}};
  e.createOperators = [](const MaterialInput& in) {
    const double capacity = in.get("Density", 0.0) * in.get("Specific Heat Capacity", 0.0);
    const auto q = in.flag("Use Improved Quadrature") ? HeatConduction::Quadrature::Moments
                                                      : HeatConduction::Quadrature::Volumes;
    std::vector<std::unique_ptr<FieldOperator>> terms;
    terms.push_back(std::unique_ptr<FieldOperator>(new HeatConduction(in.get("Coefficient"), capacity, Dimension::ThreeD,
                                                                      0.0, HeatConduction::Normalisation::Analytic, q)));
    return terms;
  };
  return e;
}

void DiffusionMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {}
void DiffusionMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  for (int b = fam.offsets[fam.begin]; b < fam.offsets[fam.end]; ++b) c[b] = 0.0;
}

}  // namespace pf
