#include "HardeningPlasticity.hpp"

namespace pf {

MaterialEntry HardeningPlasticity::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = ElasticPlasticMaterial::parameters();
  params.push_back(P::real("Isotropic Hardening Modulus", "K [Pa], linear in alpha").nonNegative().byDefault("0"));
  params.push_back(P::real("Kinematic Hardening Modulus", "H [Pa], scalar back stress").nonNegative().byDefault("0"));
  // No default: whether it was given decides which of the two names K is read from.
  params.push_back(P::real("Hardening Modulus", "Peridigm's name for the isotropic modulus K").nonNegative());
  return {"Elastic Plastic Hardening",
          "OSB J2 plasticity with linear isotropic and kinematic hardening (Pirzadeh et al. 2024)", params,
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticPlasticMaterial(in, true)); },
          ElasticPlasticMaterial::outputs()};
}

}  // namespace pf
