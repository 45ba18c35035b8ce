#include "HardeningPlasticity.hpp"

namespace pf {

MaterialEntry HardeningPlasticity::entry() {
  using K = ParameterSpec::Kind;
  std::vector<ParameterSpec> params = ElasticPlasticMaterial::parameters();
  params.push_back({"Isotropic Hardening Modulus", K::Double, false, "K [Pa], linear in alpha; default 0"});
  params.push_back({"Kinematic Hardening Modulus", K::Double, false, "H [Pa], scalar back stress; default 0"});
  params.push_back({"Hardening Modulus", K::Double, false, "Peridigm's name for the isotropic modulus K"});
  return {"Elastic Plastic Hardening",
          "OSB J2 plasticity with linear isotropic and kinematic hardening (Pirzadeh et al. 2024)", params,
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticPlasticMaterial(in, true)); },
          ElasticPlasticMaterial::outputs()};
}

}  // namespace pf
