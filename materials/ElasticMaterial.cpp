#include "ElasticMaterial.hpp"

#include "OsbKernels.hpp"
#include "OsbThermalKernels.hpp"
#include "SolidParameters.hpp"

namespace pf {

ElasticMaterial::ElasticMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), dim_(dimensionFrom(in, &thickness_)), density_(in.get("Density")),
      osb_(osbConstants(dim_, moduli_)) {
  ignoredShearCorrection(in, "Elastic");
  thermalCoefficient_ = thermalExpansionOf(in, dim_, moduli_);
}

std::vector<std::string> ElasticMaterial::fieldsRead() const {
  if (thermalCoefficient_ == 0.0) return {};
  return {"Temperature_Change"};
}

MaterialEntry ElasticMaterial::entry() {
  std::vector<ParameterSpec> params = withThermalExpansion(elasticSolidParameters());
  params.push_back(osbSurfaceCorrection());
  // Peridigm's Elastic reads no such parameter and so ignores it; its Interfaces suite deck gives one (0).
  params.push_back(ParameterSpec::real("Hourglass Coefficient", "accepted, ignored (Peridigm's Elastic has no hourglass "
                                                                "force; the correspondence models do)"));
  MaterialEntry e{"Elastic", "linear ordinary state-based solid", params,
                  [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticMaterial(in)); },
                  {"Dilatation", "Stored_Elastic_Energy", "Stored_Elastic_Energy_Density"}};
  e.createOperators = [](const MaterialInput& in) {
    double thickness = 0.0;
    const Dimension dim = dimensionFrom(in, &thickness);
    return heatTermsOf(in, dim, thickness);
  };
  return e;
}

MaterialEntry ElasticMaterial::partialVolumeEntry() {
  MaterialEntry e = entry();
  e.model = "Elastic Partial Volume";
  e.doc = "Peridigm's name for Elastic with element-horizon partial volumes; here Elastic (partial volumes: the "
          "discretization's 'Partial Volume')";
  return e;
}

std::vector<StateSpec> ElasticMaterial::stateSpecs() const {
  std::vector<StateSpec> s = {{"Dilatation", Location::Node, false, true}};
  // Peridigm defines the stored energy of its (3D) Elastic model only.
  if (dim_ == Dimension::ThreeD) {
    s.push_back({"Stored_Elastic_Energy", Location::Node, false, true});
    // Peridigm's compute class of that name: W_i itself, the energy per volume (Stored_Elastic_Energy is V_i W_i).
    s.push_back({"Stored_Elastic_Energy_Density", Location::Node, false, true});
  }
  return s;
}

void ElasticMaterial::enableOutput(const std::string& name) const {
  if (name == "Stored_Elastic_Energy") energyWanted_ = true;
  if (name == "Stored_Elastic_Energy_Density") energyWanted_ = densityWanted_ = true;
}

void ElasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                   double* force) const {
  double* theta = state.trial("Dilatation");
  if (thermalCoefficient_ != 0.0)
    osbThermoelasticDilatationAndForce(fam, osb_, thermalCoefficient_, fam.fields->find("Temperature_Change"), y,
                                       theta, force);
  else
    osbElasticDilatationAndForce(fam, osb_, y, theta, force);
  // Peridigm's Stored_Elastic_Energy: an extra bond pass, so only when an output asks for it.
  // With thermal expansion the stored energy is that of the mechanical extension (3D: e less alpha dT |xi|).
  if (energyWanted_)
    osbElasticEnergy(fam, moduli_, y, theta, state.trial("Stored_Elastic_Energy"), nullptr, nullptr,
                     thermalCoefficient_,
                     thermalCoefficient_ != 0.0 ? fam.fields->find("Temperature_Change") : nullptr);
  if (densityWanted_) {
    const double* energy = state.trial("Stored_Elastic_Energy");
    double* density = state.trial("Stored_Elastic_Energy_Density");
    for (int i = fam.begin; i < fam.end; ++i) density[i] = energy[i] / fam.volume[i];
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
  if (thermalCoefficient_ != 0.0)
    osbElasticForceDerivative(fam, osb_, y, dy, dforce, thermalCoefficient_, fam.fields->find("Temperature_Change"));
  else
    osbElasticForceDerivative(fam, osb_, y, dy, dforce);
  return true;
}
}  // namespace pf
