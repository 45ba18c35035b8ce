#include "ElasticMaterial.hpp"

#include <cmath>

#include "OsbKernels.hpp"
#include "SolidParameters.hpp"

namespace pf {

ElasticMaterial::ElasticMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), dim_(dimensionFrom(in, &thickness_)), density_(in.get("Density")),
      osb_(osbConstants(dim_, moduli_)) {}

MaterialEntry ElasticMaterial::entry() {
  return {"Elastic", "linear ordinary state-based solid", elasticSolidParameters(),
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticMaterial(in)); },
          {"Dilatation", "Stored_Elastic_Energy"}};
}

std::vector<StateSpec> ElasticMaterial::stateSpecs() const {
  std::vector<StateSpec> s = {{"Dilatation", Location::Node, false, true}};
  // Peridigm defines the stored energy of its (3D) Elastic model only.
  if (dim_ == Dimension::ThreeD) s.push_back({"Stored_Elastic_Energy", Location::Node, false, true});
  return s;
}

void ElasticMaterial::enableOutput(const std::string& name) const {
  if (name == "Stored_Elastic_Energy") energyWanted_ = true;
}

void ElasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                   double* force) const {
  double* theta = state.trial("Dilatation");
  osbElasticDilatationAndForce(fam, osb_, y, theta, force);
  if (!energyWanted_) return;
  // Stored elastic energy of node i (Peridigm's Stored_Elastic_Energy = W_i V_i):
  //   W_i = kappa theta_i^2 / 2 + (15 mu / (2 m_i)) sum_j omega_ij (e_ij - theta_i |xi_ij| / 3)^2 V_j
  // with the bond's partial-volume share of V_j when the family has one.
  double* energy = state.trial("Stored_Elastic_Energy");
  const double kappa = moduli_.bulk, alpha = 15.0 * moduli_.shear;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double* yi = y + 3 * i;
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double d0 = y[3 * j] - yi[0], d1 = y[3 * j + 1] - yi[1], d2 = y[3 * j + 2] - yi[2];
      const double xi = fam.refLength[b];
      const double ed = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2) - xi - theta[i] * xi / 3.0;
      const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      sum += fam.influence[b] * ed * ed * vj;
    }
    const double W = 0.5 * kappa * theta[i] * theta[i] + 0.5 * alpha / fam.weightedVolume[i] * sum;
    energy[i] = W * fam.volume[i];
  }
}

void ElasticMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  osbStiffnessBound(fam, osb_, bound);
}

}  // namespace pf

namespace pf {
void ElasticMaterial::pairStiffness(const FamilyView& fam, double* c) const { osbPairStiffness(fam, osb_, c); }
}  // namespace pf

namespace pf {
bool ElasticMaterial::forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore&,
                                      double* dforce) const {
  osbElasticForceDerivative(fam, osb_, y, dy, dforce);
  return true;
}
}  // namespace pf
