#include "ElasticBondBasedMaterial.hpp"

namespace pf {

MaterialEntry ElasticBondBasedMaterial::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = {
      P::real("Density", "mass density [kg/m^3]").need().positive(),
      P::real("Bulk Modulus", "K [Pa]; give this or Young's Modulus").positive(),
      P::real("Young's Modulus", "E [Pa] = 3K(1 - 2 nu), nu = 1/4 (3D, plane strain) or 1/3 (plane stress)")
          .positive(),
      P::flag("Plane Stress", "2D plane-stress model (c = 12K/(pi h delta^3); needs Height)").byDefault("false"),
      P::flag("Plane Strain", "2D plane-strain model (c = 12K/(pi h delta^3); needs Height)").byDefault("false"),
      P::real("Height", "out-of-plane thickness h of a 2D model [m] (Peridigm's name)").positive(),
  };
  return MaterialEntry{"Elastic Bond Based",
                       "Peridigm's bond-based elastic solid (its micromodulus; breaks with a Damage Model)",
                       params,
                       [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticBondBasedMaterial(in)); },
                       {"Stored_Elastic_Energy"}};
}

}  // namespace pf
