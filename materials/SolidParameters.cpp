#include "SolidParameters.hpp"

namespace pf {

std::vector<ParameterSpec> elasticSolidParameters() {
  using P = ParameterSpec;
  // Ranges the input layer enforces; which two moduli are given, and whether they make a positive bulk
  // and shear modulus, is checked where they are combined (elasticModuliFrom).
  return {
      P::real("Density", "mass density [kg/m^3]").need().positive(),
      P::real("Bulk Modulus", "give exactly two of the four elastic constants").positive(),
      P::real("Shear Modulus").positive(),
      P::real("Young's Modulus").positive(),
      P::real("Poisson's Ratio").above(-1.0).below(0.5),
      P::flag("Plane Stress", "2D plane-stress model (points in z = 0, needs Thickness)").byDefault("false"),
      P::flag("Plane Strain", "2D plane-strain model (points in z = 0, needs Thickness)").byDefault("false"),
      P::real("Thickness", "out-of-plane thickness of a 2D model [m]").positive(),
      // Peridigm options accepted for deck compatibility; Periforge's tangent is analytic and its
      // influence function is set under Discretization, so these change nothing.
      P::flag("Apply Automatic Differentiation Jacobian", "accepted, ignored (Peridigm)").byDefault("false"),
      P::flag("Apply Shear Correction Factor", "accepted; only false is supported").byDefault("false"),
  };
}

}  // namespace pf
