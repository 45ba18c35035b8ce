#pragma once
// "Elastic Plastic Hardening": OSB J2 plasticity with Peridigm's hardening law ("Hardening Modulus") or the
// paper's linear isotropic (K) and kinematic (H) hardening (Pirzadeh et al. 2024), and Peridigm's shear
// correction factor. Built on ElasticPlasticMaterial; no hardening reproduces "Elastic Plastic".
#include "ElasticPlasticMaterial.hpp"

namespace pf {

struct HardeningPlasticity {
  static MaterialEntry entry();
};

}  // namespace pf
