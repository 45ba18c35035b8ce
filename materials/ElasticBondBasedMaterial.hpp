#pragma once
// "Elastic Bond Based": Peridigm's bond-based elastic solid (src/materials/Peridigm_ElasticBondBasedMaterial.cpp,
// elastic_bond_based.cxx). The pair force is Microelastic's, f = c s M (half from each end), with Peridigm's
// micromodulus: 3D c = 18K/(pi delta^4) (Microelastic's), 2D (plane stress and plane strain alike)
// c = 12K/(pi h delta^3), h the "Height". No influence function (omega = 1 whatever the discretization's) and no
// thermal expansion, as Peridigm's. K from "Bulk Modulus" or from "Young's Modulus" with nu = 1/4 (3D, plane
// strain) or 1/3 (plane stress); Peridigm refuses a Poisson's ratio or shear modulus, and so does the registry.
#include "MicroelasticMaterial.hpp"

namespace pf {

class ElasticBondBasedMaterial : public MicroelasticMaterial {
 public:
  explicit ElasticBondBasedMaterial(const MaterialInput& in)
      : MicroelasticMaterial(in, Calibration{"Height", true, false}) {}
  static MaterialEntry entry();
};

}  // namespace pf
