#include "MaterialRegistry.hpp"

#include "ElasticMaterial.hpp"
#include "ElasticPlasticMaterial.hpp"
#include "HardeningPlasticity.hpp"
#include "InputError.hpp"

namespace pf {

const std::vector<MaterialEntry>& materialRegistry() {
  // One line per model.
  static const std::vector<MaterialEntry> entries = {
      ElasticMaterial::entry(),
      ElasticPlasticMaterial::entry(),
      HardeningPlasticity::entry(),
  };
  return entries;
}

const MaterialEntry* findMaterial(const std::string& model) {
  for (const MaterialEntry& e : materialRegistry())
    if (e.model == model) return &e;
  return nullptr;
}

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
      {"Material Model", K::String, true, "name of the model in the registry"},
  };
}

double MaterialInput::get(const std::string& key) const {
  auto it = values.find(key);
  if (it == values.end())
    throw InputError(inputFile + ": material '" + name + "' needs parameter '" + key + "'");
  return it->second;
}

double MaterialInput::get(const std::string& key, double fallback) const {
  auto it = values.find(key);
  return it == values.end() ? fallback : it->second;
}

}  // namespace pf
