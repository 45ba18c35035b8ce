#include "HardeningPlasticity.hpp"

#include "SolidParameters.hpp"

namespace pf {

MaterialEntry HardeningPlasticity::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = ElasticPlasticMaterial::parameters(true);
  params.push_back(P::real("Isotropic Hardening Modulus", "the paper's K [Pa], linear in alpha (Eq. 39)")
                       .nonNegative().byDefault("0"));
  params.push_back(P::real("Kinematic Hardening Modulus", "the paper's H [Pa], scalar back stress (Eq. 56)")
                       .nonNegative().byDefault("0"));
  // No default: given, it selects Peridigm's law (and excludes the paper's two moduli).
  params.push_back(P::real("Hardening Modulus",
                           "Peridigm's H: yield when |t^d|^2/2 - psi0 - H lambda > 0 (elastic_plastic_hardening.cxx; "
                           "3D); H in psi per unit lambda, not Pa")
                       .nonNegative());
  params = withThermalExpansion(params, true);
  MaterialEntry e{"Elastic Plastic Hardening",
                  "OSB J2 plasticity with linear hardening: Peridigm's law (Hardening Modulus) or isotropic and "
                  "kinematic hardening (Pirzadeh et al. 2024)", params,
                  [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticPlasticMaterial(in, true)); },
                  ElasticPlasticMaterial::outputs()};
  e.createOperators = ElasticPlasticMaterial::heatTerms;
  return e;
}

}  // namespace pf
