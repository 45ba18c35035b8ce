#include "SolidParameters.hpp"

namespace pf {

std::vector<ParameterSpec> elasticSolidParameters() {
  using K = ParameterSpec::Kind;
  return {
      {"Density", K::Double, true, "mass density [kg/m^3]"},
      {"Bulk Modulus", K::Double, false, "give exactly two of the four elastic constants"},
      {"Shear Modulus", K::Double, false, ""},
      {"Young's Modulus", K::Double, false, ""},
      {"Poisson's Ratio", K::Double, false, ""},
      {"Plane Stress", K::Bool, false, "2D plane-stress model (points in z = 0, needs Thickness)"},
      {"Plane Strain", K::Bool, false, "2D plane-strain model (points in z = 0, needs Thickness)"},
      {"Thickness", K::Double, false, "out-of-plane thickness of a 2D model [m]"},
      // Peridigm options accepted for deck compatibility; Periforge's tangent is analytic and its
      // influence function is set under Discretization, so these change nothing.
      {"Apply Automatic Differentiation Jacobian", K::Bool, false, "accepted, ignored (Peridigm)"},
      {"Apply Shear Correction Factor", K::Bool, false, "accepted; only false is supported"},
  };
}

}  // namespace pf
