#include "SolidParameters.hpp"

#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "core/MaterialEntry.hpp"
#include "core/ElasticModuli.hpp"
#include "HeatConduction.hpp"
#include "PlasticHeating.hpp"

namespace pf {

std::vector<ParameterSpec> elasticSolidParameters(ShearCorrection scf) {
  using P = ParameterSpec;
  // Ranges the input layer enforces; which two moduli are given, and whether they make a positive bulk
  // and shear modulus, is checked where they are combined (elasticModuliFrom).
  std::vector<ParameterSpec> params = {
      P::real("Density", "mass density [kg/m^3]").need().positive(),
      P::real("Bulk Modulus", "give exactly two of the four elastic constants").positive(),
      P::real("Shear Modulus").positive(),
      P::real("Young's Modulus").positive(),
      P::real("Poisson's Ratio").above(-1.0).below(0.5),
      P::flag("Plane Stress", "2D plane-stress model (points in z = 0, needs Thickness)").byDefault("false"),
      P::flag("Plane Strain", "2D plane-strain model (points in z = 0, needs Thickness)").byDefault("false"),
      P::real("Thickness", "out-of-plane thickness of a 2D model [m]").positive(),
      // Peridigm option accepted for deck compatibility; Periforge's tangent is analytic or numerical by
      // solver, so it changes nothing.
      P::flag("Apply Automatic Differentiation Jacobian", "accepted, ignored (Peridigm)").byDefault("false"),
  };
  if (scf == ShearCorrection::Peridigm3D)
    // No default in the spec: it depends on the dimension (Peridigm's factor is a 3D construction).
    params.push_back(P::flag("Apply Shear Correction Factor",
                             "Peridigm's per-node shear correction factor (docs/materials.md); default true in "
                             "3D as in Peridigm, false in 2D (true is an error there)"));
  else
    params.push_back(P::flag("Apply Shear Correction Factor",
                             "Peridigm's model of this name has no shear correction: true is ignored, with a "
                             "warning, as Peridigm ignores it").byDefault("false"));
  return params;
}

ParameterSpec osbSurfaceCorrection() {
  return ParameterSpec::text("Surface Correction",
                             "`Position Aware`: each point's influence becomes omega exp(xi.L xi/|xi|^2), L solved per "
                             "point so that its family's second moment is isotropic (m unchanged): the dilatation is "
                             "exact for every small affine strain near a free surface too; points where no positive "
                             "weights do it (convex lattice corners and edges) keep omega (docs/materials.md, \"Surface "
                             "correction\"); `None`: Peridigm's model")
      .oneOf({"None", "Position Aware"})
      .byDefault("None");
}

bool shearCorrectionOf(const MaterialInput& in, Dimension dim) {
  if (!in.has("Apply Shear Correction Factor")) return dim == Dimension::ThreeD;
  const bool on = in.flag("Apply Shear Correction Factor");
  if (on && dim != Dimension::ThreeD)
    throw InputError(in.inputFile + ": material '" + in.name + "': 'Apply Shear Correction Factor' is true, "
                     "but Peridigm's shear correction factor is defined for 3D families only; set it false for "
                     "Plane Stress / Plane Strain");
  return on;
}

bool ignoredShearCorrection(const MaterialInput& in, const std::string& model) {
  if (in.has("Apply Shear Correction Factor") && in.flag("Apply Shear Correction Factor"))
    warn(in.inputFile + ": material '" + in.name + "': 'Apply Shear Correction Factor' = true is ignored: "
         "Peridigm's '" + model + "' model has no shear correction (it ignores the parameter too)");
  return false;
}

std::vector<ParameterSpec> withThermalExpansion(std::vector<ParameterSpec> params, bool plasticHeating) {
  params.push_back(ParameterSpec::real("Thermal Expansion Coefficient",
                                       "linear thermal expansion coefficient alpha [1/K]; the material then reads the "
                                       "Temperature field (docs/input.md, \"Temperature\"), relative to each point's "
                                       "start temperature"));
  for (ParameterSpec& p : heatParameters(plasticHeating)) params.push_back(std::move(p));
  return params;
}

std::vector<ParameterSpec> heatParameters(bool plasticHeating) {
  std::vector<ParameterSpec> params = {
      ParameterSpec::real("Thermal Conductivity", "k [W/(m K)]: the block conducts heat (docs/thermal.md; bond rule "
                                                  "normalised on each point's family)").positive(),
      ParameterSpec::real("Specific Heat Capacity", "c [J/(kg K)]: with Density the heat capacity of a transient "
                                                    "thermal solve").positive()};
  if (plasticHeating)
    params.push_back(ParameterSpec::real("Taylor-Quinney Coefficient",
                                         "beta: the fraction of the plastic work (Dissipated_Energy) that heats the "
                                         "point, when a solver advances Temperature (needs Specific Heat Capacity; "
                                         "docs/thermal.md)").nonNegative().atMost(1.0));
  return params;
}

std::unique_ptr<FieldOperator> conductionOf(const MaterialInput& in, Dimension dim, double thickness) {
  if (!in.has("Thermal Conductivity")) return nullptr;
  const double capacity = in.get("Density", 0.0) * in.get("Specific Heat Capacity", 0.0);
  return std::unique_ptr<FieldOperator>(new HeatConduction(in.get("Thermal Conductivity"), capacity, dim, thickness,
                                                           HeatConduction::Normalisation::Family));
}

std::vector<std::unique_ptr<FieldOperator>> heatTermsOf(const MaterialInput& in, Dimension dim, double thickness) {
  std::vector<std::unique_ptr<FieldOperator>> terms;
  if (auto k = conductionOf(in, dim, thickness)) terms.push_back(std::move(k));
  if (in.has("Taylor-Quinney Coefficient")) {
    if (!in.has("Specific Heat Capacity"))
      throw InputError(in.where() + ": 'Taylor-Quinney Coefficient' needs 'Specific Heat Capacity' (the heat "
                                    "capacity its plastic work heats)");
    terms.push_back(std::unique_ptr<FieldOperator>(
        new PlasticHeating(in.get("Taylor-Quinney Coefficient"), in.get("Density") * in.get("Specific Heat Capacity"))));
  }
  return terms;
}

double thermalExpansionOf(const MaterialInput& in, Dimension dim, const ElasticModuli& moduli) {
  const double alpha = in.get("Thermal Expansion Coefficient", 0.0);
  return dim == Dimension::PlaneStrain ? (1.0 + moduli.poisson) * alpha : alpha;
}

}  // namespace pf
