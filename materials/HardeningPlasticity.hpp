#pragma once
// "Elastic Plastic Hardening": OSB J2 plasticity with linear isotropic (K) and kinematic (H) hardening
// (Pirzadeh et al. 2024). Built on ElasticPlasticMaterial; K = H = 0 reproduces "Elastic Plastic".
#include "ElasticPlasticMaterial.hpp"

namespace pf {

struct HardeningPlasticity {
  static MaterialEntry entry();
};

}  // namespace pf
