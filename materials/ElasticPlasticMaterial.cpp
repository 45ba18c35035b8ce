#include "ElasticPlasticMaterial.hpp"

#include <algorithm>
#include <vector>

#include "core/InputError.hpp"
#include "OsbKernels.hpp"
#include "OsbPlasticTangent.hpp"
#include "OsbThermalKernels.hpp"
#include "ShearCorrectionFactor.hpp"
#include "SolidParameters.hpp"

namespace pf {

namespace {

// Peridigm's H or the paper's K and H: two laws, one per deck (InputError naming both if both are given).
void readHardening(const MaterialInput& in, J2Parameters& p) {
  const std::string where = in.inputFile + ": material '" + in.name + "'";
  std::string paper;
  for (const char* n : {"Isotropic Hardening Modulus", "Kinematic Hardening Modulus"})
    if (in.has(n)) paper += (paper.empty() ? "'" : " and '") + std::string(n) + "'";
  if (in.has("Hardening Modulus")) {
    if (!paper.empty())
      throw InputError(where + ": 'Hardening Modulus' (Peridigm's H, yield when |t^d|^2/2 - psi0 - H lambda > 0) "
                       "and " + paper + " (Pirzadeh et al.'s moduli in Pa) are two different hardening laws: "
                       "give one of them");
    if (p.dim != Dimension::ThreeD)
      throw InputError(where + ": Peridigm's 'Hardening Modulus' law is 3D only (Peridigm's "
                       "elastic_plastic_hardening.cxx has no planar yield value); in 2D use "
                       "'Isotropic Hardening Modulus' / 'Kinematic Hardening Modulus'");
    p.peridigmLaw = true;
    p.peridigmHardening = in.get("Hardening Modulus");
    return;
  }
  p.isoHardening = in.get("Isotropic Hardening Modulus");
  p.kinHardening = in.get("Kinematic Hardening Modulus");
}

}  // namespace

ElasticPlasticMaterial::ElasticPlasticMaterial(const MaterialInput& in, bool hardening)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")) {
  params_.dim = dimensionFrom(in, &params_.thickness);
  params_.osb = osbConstants(params_.dim, moduli_);
  params_.yieldStress = in.get("Yield Stress");  // >= 0: its spec's range, as every range below
  // Peridigm's "Disable Plasticity": the model is its elastic part and the yield stress is not used (its
  // BondBreakingInitialVelocity-EP deck gives Yield Stress = 0 with it, and its gold file is the Elastic one's).
  disablePlasticity_ = !hardening && in.flag("Disable Plasticity");
  if (!(params_.yieldStress > 0.0) && !disablePlasticity_)
    throw InputError(in.inputFile + ": material '" + in.name + "': 'Yield Stress' = 0: must be > 0" +
                     (hardening ? std::string("") : std::string(" (or set 'Disable Plasticity' = true)")));
  if (hardening) readHardening(in, params_);
  params_.norm = in.text("Yield Normalization") == "Continuum" ? YieldNormalization::Continuum
                                                                : YieldNormalization::Discrete;
  shearCorrection_ = hardening ? shearCorrectionOf(in, params_.dim) : ignoredShearCorrection(in, "Elastic Plastic");
  alpha_ = in.get("Thermal Expansion Coefficient", 0.0);
  params_.gradientCorrection = in.text("Gradient Correction") == "Quadratic";
  if (params_.gradientCorrection && alpha_ != 0.0)
    throw InputError(in.where() + ": 'Gradient Correction' = Quadratic is not implemented with thermal expansion "
                                  "('Thermal Expansion Coefficient' given): remove one of them");
  elasticThermal_ = thermalExpansionOf(in, params_.dim, moduli_);
  // J2Thermal (OsbPlasticKernels.hpp): plane strain's thermal strain is hydrostatic (volume term only).
  if (params_.dim == Dimension::PlaneStrain) thermal_ = {0.0, elasticThermal_, 3.0 * alpha_};
  else thermal_ = {alpha_, alpha_, 0.0};
}

std::vector<std::string> ElasticPlasticMaterial::fieldsRead() const {
  if (alpha_ == 0.0) return {};
  return {"Temperature_Change"};
}

std::vector<std::unique_ptr<FieldOperator>> ElasticPlasticMaterial::heatTerms(const MaterialInput& in) {
  double thickness = 0.0;
  const Dimension dim = dimensionFrom(in, &thickness);
  return heatTermsOf(in, dim, thickness);
}

std::vector<ParameterSpec> ElasticPlasticMaterial::parameters(bool hardening) {
  std::vector<ParameterSpec> params = elasticSolidParameters(hardening ? ShearCorrection::Peridigm3D
                                                                       : ShearCorrection::IgnoredAsPeridigm);
  params.push_back(ParameterSpec::real("Yield Stress", "initial uniaxial yield stress sigma_y0 [Pa]; > 0 unless "
                                       "plasticity is disabled").need().nonNegative());
  if (!hardening)
    params.push_back(ParameterSpec::flag("Disable Plasticity", "Peridigm's switch: true = the Elastic model's "
                                         "force and dilatation, Yield Stress unused").byDefault("false"));
  params.push_back(ParameterSpec::text("Yield Normalization",
                                       "'Continuum': the paper's and Peridigm's 4 pi delta^5/5, pi h delta^4/2; "
                                       "'Discrete': yield constants from the node's weighted volume m "
                                       "(lattice-consistent; docs/materials.md)")
                       .oneOf({"Discrete", "Continuum"})
                       .byDefault("Continuum"));
  params.push_back(osbSurfaceCorrection());
  params.push_back(ParameterSpec::text("Gradient Correction",
                                       "`Quadratic`: each point reads its state from its bonds with the quadratic part "
                                       "of the deformation removed (a weighted least-squares fit over its family), so a "
                                       "surface point's one-sided family reads the strain at the point, not inside the "
                                       "body (docs/materials.md, \"Gradient correction\"); `None`: the paper's reading")
                       .oneOf({"None", "Quadratic"})
                       .byDefault("None"));
  return params;
}

MaterialEntry ElasticPlasticMaterial::entry() {
  MaterialEntry e{"Elastic Plastic", "OSB J2 elastic-perfectly plastic solid (Mitchell 2011)",
                  withThermalExpansion(parameters(false), true),
                  [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticPlasticMaterial(in, false)); },
                  outputs()};
  e.createOperators = heatTerms;
  return e;
}

std::vector<std::string> ElasticPlasticMaterial::outputs() {
  std::vector<std::string> names;
  for (const StateSpec& s : states())
    if (s.output) names.push_back(s.name);
  names.push_back("Stored_Elastic_Energy");  // 3D (stateSpecs)
  return names;
}

std::vector<StateSpec> ElasticPlasticMaterial::stateSpecs() const {
  std::vector<StateSpec> s = states();
  // As Elastic's (Peridigm's 3D definition), with the elastic part e^d - e^dp of the deviatoric extension.
  if (params_.dim == Dimension::ThreeD) s.push_back({"Stored_Elastic_Energy", Location::Node, false, true});
  return s;
}

void ElasticPlasticMaterial::enableOutput(const std::string& name) const {
  if (name == "Stored_Elastic_Energy") energyWanted_ = true;
}

std::vector<StateSpec> ElasticPlasticMaterial::states() {
  return {{"Deviatoric_Plastic_Extension", Location::Bond, true, false},
          {"Lambda", Location::Node, true, true},
          {"Equivalent_Plastic_Strain", Location::Node, true, true},
          {"Back_Stress", Location::Node, true, true},
          {"Von_Mises_Sign", Location::Node, true, false},
          {"Von_Mises_Stress", Location::Node, false, true},
          {"Signed_Von_Mises_Stress", Location::Node, false, true},
          {"Dilatation", Location::Node, false, true},
          {"Return_Mapping_Iterations", Location::Node, false, false},
          // The plastic work [J per node] (OsbPlasticKernels.hpp J2Fields), heat with a Taylor-Quinney Coefficient.
          {"Dissipated_Energy", Location::Node, true, true},
          // Not history: set on the first evaluation from the reference family and kept (Peridigm's name).
          {"Surface_Correction_Factor", Location::Node, false, true}};
}

namespace {
// The committed (n) history the return mapping starts from; the trial pointers are left null.
J2Fields committedFields(const StateStore& state) {
  J2Fields f{};
  f.edpN = state.committed("Deviatoric_Plastic_Extension");
  f.lambdaN = state.committed("Lambda");
  f.alphaN = state.committed("Equivalent_Plastic_Strain");
  f.qN = state.committed("Back_Stress");
  f.signN = state.committed("Von_Mises_Sign");
  return f;
}
}  // namespace

void ElasticPlasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                          double* force) const {
  J2Fields f = committedFields(state);
  f.edp = state.trial("Deviatoric_Plastic_Extension");
  f.lambda = state.trial("Lambda");
  f.alpha = state.trial("Equivalent_Plastic_Strain");
  f.q = state.trial("Back_Stress");
  f.sign = state.trial("Von_Mises_Sign");
  f.vonMises = state.trial("Von_Mises_Stress");
  f.signedVonMises = state.trial("Signed_Von_Mises_Stress");
  f.theta = state.trial("Dilatation");
  f.iterations = state.trial("Return_Mapping_Iterations");
  f.dissipatedN = state.committed("Dissipated_Energy");
  f.dissipated = state.trial("Dissipated_Energy");
  double* scf = state.trial("Surface_Correction_Factor");
  if (fam.begin < fam.end && !(scf[fam.begin] > 0.0)) {  // first evaluation of this block: 0 = not yet set
    if (shearCorrection_) osbShearCorrectionFactor(fam, scf);
    else std::fill(scf + fam.begin, scf + fam.end, 1.0);
  }
  f.scf = shearCorrection_ ? scf : nullptr;
  // Disabled plasticity: the history fields stay at their initial zeros in both copies (never written, so
  // StateStore::commit swaps zeros), the dilatation and force are the Elastic model's.
  if (alpha_ != 0.0) {  // thermal expansion: the thermal kernels, so the mechanics-only ones stay as they are
    const double* dT = fam.fields->find("Temperature_Change");
    if (disablePlasticity_)
      osbThermoelasticDilatationAndForce(fam, params_.osb, elasticThermal_, dT, y, f.theta, force);
    else
      osbJ2ThermalForce(fam, params_, thermal_, dT, y, f, force);
  } else if (disablePlasticity_) {
    osbElasticDilatationAndForce(fam, params_.osb, y, f.theta, force);
  } else {
    osbJ2Force(fam, params_, y, f, force);
  }
  // An extra bond pass, only when an output asks for it (3D: the thermal extension alpha dT |xi| taken out).
  if (energyWanted_)
    osbElasticEnergy(fam, moduli_, y, f.theta, state.trial("Stored_Elastic_Energy"),
                     disablePlasticity_ ? nullptr : f.edp, f.scf, alpha_,
                     alpha_ != 0.0 ? fam.fields->find("Temperature_Change") : nullptr);
}

namespace {
// The committed fields the tangent reads, with the shear correction factor: set by the first force evaluation
// (computeForce); a derivative before any computes it into own.
J2Fields tangentFields(const FamilyView& fam, const StateStore& state, bool shearCorrection, std::vector<double>& own) {
  J2Fields f = committedFields(state);
  const double* scf = state.committed("Surface_Correction_Factor");  // not history: the trial array
  if (shearCorrection && fam.begin < fam.end && !(scf[fam.begin] > 0.0)) {
    own.assign(static_cast<std::size_t>(fam.end), 1.0);
    osbShearCorrectionFactor(fam, own.data());
    scf = own.data();
  }
  f.scf = shearCorrection ? scf : nullptr;
  return f;
}

// The consistent tangent kept at one point (OsbPlasticTangent.hpp J2Tangent).
class J2Linearisation : public MaterialLinearisation {
 public:
  J2Linearisation(const J2Parameters& p, bool shearCorrection) : p_(p), shearCorrection_(shearCorrection) {}
  // The committed fields read at update stay in place until the next: the state commits between Newton solves.
  bool update(const FamilyView& fam, const double* y, const StateStore& state) override {
    fields_ = tangentFields(fam, state, shearCorrection_, ownScf_);
    return osbJ2Linearise(fam, p_, y, fields_, tangent_);
  }
  void apply(const FamilyView& fam, const double* dy, double* dforce) const override {
    osbJ2TangentProduct(fam, p_, fields_, tangent_, dy, dforce);
  }
  std::size_t bytes() const override { return tangent_.bytes(); }

 private:
  J2Parameters p_;
  bool shearCorrection_;
  J2Fields fields_{};
  std::vector<double> ownScf_;
  J2Tangent tangent_;
};
}  // namespace

bool ElasticPlasticMaterial::forceDerivative(const FamilyView& fam, const double* y, const double* dy,
                                             const StateStore& state, double* dforce) const {
  if (disablePlasticity_) {
    osbElasticForceDerivative(fam, params_.osb, y, dy, dforce);
    return true;
  }
  std::vector<double> own;
  return osbJ2ForceDerivative(fam, params_, y, dy, tangentFields(fam, state, shearCorrection_, own), dforce);
}

std::unique_ptr<MaterialLinearisation> ElasticPlasticMaterial::makeLinearisation() const {
  // The elastic tangent (Disable Plasticity) has no per-point work to keep.
  if (!hasForceDerivative() || disablePlasticity_) return nullptr;
  return std::make_unique<J2Linearisation>(params_, shearCorrection_);
}

void ElasticPlasticMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  // The elastic bound also bounds the plastic tangent (the return only softens the deviatoric part).
  osbStiffnessBound(fam, params_.osb, bound);
  if (!shearCorrection_) return;
  // The factor stiffens the deviatoric terms by s (s_i for node i's bonds, s_j for the force t_ji a
  // neighbour sends back). A ghost's s_j is not known here, so the bound is scaled by max(1, s_i): exact for
  // uniform s (the interior); near faces, where s runs from 0.51 to 1.37 (40^3 cube), the elastic bound's
  // slack covers it -- on a 7^3 cube, all of it within a horizon of a face, the finite-difference row sums
  // reach 0.49 of the bound with the factor and without (test PeridigmHardening.StiffnessBoundWithShearCorrection).
  std::vector<double> scf(static_cast<std::size_t>(fam.end), 1.0);
  osbShearCorrectionFactor(fam, scf.data());
  for (int i = fam.begin; i < fam.end; ++i) bound[i] *= std::max(1.0, scf[i]);
}

void ElasticPlasticMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  osbPairStiffness(fam, params_.osb, c);  // elastic moduli: a preconditioner (core/Material.hpp)
}

}  // namespace pf
