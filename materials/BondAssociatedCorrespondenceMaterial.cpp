#include "BondAssociatedCorrespondenceMaterial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "BondAssociatedKinematics.hpp"
#include "BondAssociatedCommon.hpp"
#include "BondTensorFields.hpp"
#include "CorrespondenceLawParameters.hpp"
#include "CorrespondenceKinematics.hpp"
#include "core/InputError.hpp"

namespace pf {
namespace {

using Law = BondAssociatedCorrespondenceMaterial::Law;
const double kTag = 7.0;  // marks a row written by a bond-associated model (a neighbour of another model leaves 0)

const char* modelName(Law law) {
  switch (law) {
    case Law::Elastic: return "Elastic Bond Associated Correspondence";
    case Law::PerfectPlastic: return "Elastic Plastic Bond Associated Correspondence";
    case Law::IsotropicHardening: return "Isotropic Hardening Bond Associated Correspondence";
    case Law::DruckerPrager: return "Drucker Prager Bond Associated Correspondence";
    case Law::Viscoplastic: break;
  }
  return "Viscoplastic Bond Associated Correspondence";
}

const char* summary(Law law) {
  switch (law) {
    case Law::Elastic:
      return "bond-associated hypoelastic correspondence solid: a deformation gradient, rotation and stress per bond, "
             "no hourglass force (Peridigm; Chen & Spencer 2019)";
    case Law::PerfectPlastic:
      return "bond-associated correspondence solid with Peridigm's elastic perfectly plastic J2 return per bond (the "
             "law of Elastic Plastic Correspondence), no hourglass force";
    case Law::IsotropicHardening:
      return "bond-associated correspondence solid with Peridigm's linear isotropic hardening J2 return per bond (the "
             "law of Isotropic Hardening Correspondence), no hourglass force";
    case Law::DruckerPrager:
      return "bond-associated correspondence solid with Li & Geng's Drucker-Prager update per bond (the law of Drucker "
             "Prager Correspondence; 3D, no surface band, no loading-balance rounds), no hourglass force";
    case Law::Viscoplastic: break;
  }
  return "bond-associated correspondence solid with Foster, Silling & Chen (2010)'s rate-dependent J2 update per bond "
         "(the law of Viscoplastic Correspondence, without thermal softening), no hourglass force";
}

std::vector<ParameterSpec> parametersOf(Law law) {
  std::vector<ParameterSpec> params = bondAssociatedParameters();
  std::vector<ParameterSpec> own = law == Law::Elastic         ? std::vector<ParameterSpec>{}
                                   : law == Law::Viscoplastic  ? fosterParameters()
                                   : law == Law::DruckerPrager ? druckerPragerParameters()
                                                               : peridigmJ2Parameters(law == Law::IsotropicHardening);
  params.insert(params.end(), own.begin(), own.end());
  return params;
}

std::unique_ptr<BondStressLaw> lawFrom(const MaterialInput& in, Law law, const ElasticModuli& m) {
  switch (law) {
    case Law::Elastic: return hookeBondLaw(m.bulk, m.shear);
    case Law::PerfectPlastic: return perfectPlasticBondLaw(m.bulk, m.shear, in.get("Yield Stress"));
    case Law::IsotropicHardening:
      return isotropicHardeningBondLaw(m.bulk, m.shear, in.get("Yield Stress"), in.get("Hardening Modulus"));
    case Law::DruckerPrager: return druckerPragerBondLaw(m.bulk, m.shear, druckerPragerLawFrom(in));
    case Law::Viscoplastic: break;
  }
  return fosterBondLaw(m.bulk, m.shear, fosterLawFrom(in));
}

MaterialEntry entryOf(Law law) {
  return {modelName(law), summary(law), parametersOf(law),
          [law](const MaterialInput& in) {
            return std::unique_ptr<Material>(new BondAssociatedCorrespondenceMaterial(in, law));
          },
          law == Law::Elastic
              ? bondAssociatedOutputs({"Stored_Elastic_Energy", "Dissipated_Energy"}, {})
              : bondAssociatedOutputs({"Stored_Elastic_Energy", "Dissipated_Energy", "Equivalent_Plastic_Strain"}, {})};
}

}  // namespace

BondAssociatedCorrespondenceMaterial::BondAssociatedCorrespondenceMaterial(const MaterialInput& in, Law law)
    : model_(modelName(law)), moduli_(elasticModuliFrom(in)), law_(lawFrom(in, law, moduli_)), density_(in.get("Density")) {
  requireFirstOrderGradients(in);
}

MaterialEntry BondAssociatedCorrespondenceMaterial::elasticEntry() { return entryOf(Law::Elastic); }
MaterialEntry BondAssociatedCorrespondenceMaterial::perfectPlasticEntry() { return entryOf(Law::PerfectPlastic); }
MaterialEntry BondAssociatedCorrespondenceMaterial::hardeningEntry() { return entryOf(Law::IsotropicHardening); }
MaterialEntry BondAssociatedCorrespondenceMaterial::viscoplasticEntry() { return entryOf(Law::Viscoplastic); }
MaterialEntry BondAssociatedCorrespondenceMaterial::druckerPragerEntry() { return entryOf(Law::DruckerPrager); }

std::vector<StateSpec> BondAssociatedCorrespondenceMaterial::stateSpecs() const {
  std::vector<StateSpec> s;
  addBondAssociatedSpecs(s);
  s.push_back({"Stored_Elastic_Energy", Location::Node, false, true});
  s.push_back({"Dissipated_Energy", Location::Node, true, true});
  if (law_->hasHistory()) {
    s.push_back({"Equivalent_Plastic_Strain", Location::Node, true, true});
    s.push_back({"Bond_Equivalent_Plastic_Strain", Location::Bond, true, false});
  }
  return s;
}

void BondAssociatedCorrespondenceMaterial::enableOutput(const std::string& name) const {
  if (name.rfind("Cauchy_Stress", 0) == 0) cauchyWanted_ = true;
  if (name.rfind("Unrotated_Rate_Of_Deformation", 0) == 0) rateWanted_ = true;
  if (name == "Stored_Elastic_Energy") storedWanted_ = true;
  if (name == "Dissipated_Energy") dissipatedWanted_ = true;
}

void BondAssociatedCorrespondenceMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                        double* force) const {
  if (fam.exchange) {
    nodePhase(fam, y, state, fam.exchange, fam.exchangeStride);
    return;
  }
  std::vector<double> rows(static_cast<std::size_t>(fam.numNodes) * kRow, 0.0);
  nodePhase(fam, y, state, rows.data(), kRow);
  bondPhase(fam, y, state, rows.data(), kRow, force);
}

void BondAssociatedCorrespondenceMaterial::completeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                         double* force) const {
  bondPhase(fam, y, state, fam.exchange, fam.exchangeStride, force);
}

// Peridigm's node level (computeNodeLevelUnrotatedRateOfDeformationAndRotationTensor, updateElasticCauchyStress):
// F from the first-order gradient weights (= the shape-tensor gradient), F-dot dt from the velocities (or the step's
// increment), the first-order polar update, tau = tau_n + C : d dt. These are outputs only; the force uses the bonds'.
void BondAssociatedCorrespondenceMaterial::nodePhase(const FamilyView& fam, const double* y, StateStore& state,
                                                     double* rows, int stride) const {
  TensorField Fs(state, "Deformation_Gradient", false), Rs(state, "Rotation_Tensor", false),
      Vs(state, "Left_Stretch_Tensor", false), taus(state, "Unrotated_Cauchy_Stress", true);
  double* vm = state.trial("Von_Mises_Stress");
  const double* timeN = state.committed("Correspondence_Time");
  // The optional outputs: the fields always exist, written only when an output asks (enableOutput).
  TensorField rate(state, "Unrotated_Rate_Of_Deformation", true), cauchy(state, "Cauchy_Stress", true);
  double* time = state.trial("Correspondence_Time");
  const bool history = law_->hasHistory();
  const double* epsN = history ? state.committed("Equivalent_Plastic_Strain") : nullptr;
  double* eps = history ? state.trial("Equivalent_Plastic_Strain") : nullptr;
  const double* ref = fam.yN ? fam.yN : fam.x;  // the committed positions (the reference before the first commit)
  for (int i = fam.begin; i < fam.end; ++i) {
    const double dt = bondAssociatedStepLength(fam, timeN, i);
    time[i] = fam.time;
    const ShapeAndGradient sg = shapeAndGradient(fam, i, y, false);
    requirePositiveJacobian(fam, i, y, sg.F);
    const Mat3 dF = fam.velocity ? dt * velocityGradient(fam, i, fam.velocity, sg.Kinv, false)
                                 : sg.F - mul(familySums(fam, i, ref, false).N, sg.Kinv);
    const PolarUpdate pu = peridigmPolarUpdate(dF, sg.F, Rs.committedAt(i), Vs.committedAt(i));
    double h = 0.0;
    const Mat3 tau = law_->update(taus.committedAt(i), history ? epsN[i] : 0.0, pu.dUnrot, dt, h);
    if (history) eps[i] = h;
    Fs.set(i, sg.F), Rs.set(i, pu.R), Vs.set(i, pu.V), taus.set(i, tau);
    vm[i] = vonMises(tau);
    if (rateWanted_) rate.set(i, dt > 0.0 ? (1.0 / dt) * pu.dUnrot : rate.committedAt(i));
    if (cauchyWanted_) cauchy.set(i, mul(pu.R, mulNT(tau, pu.R)));
    double w0 = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) w0 += bondWeight(fam, b);
    double* row = rows + static_cast<std::size_t>(stride) * i;
    std::copy(sg.F.begin(), sg.F.end(), row + kRowF);
    std::copy(dF.begin(), dF.end(), row + kRowDF);
    std::copy(sg.Kinv.begin(), sg.Kinv.end(), row + kRowKinv);
    row[kRowW0] = w0;
    row[kRowTag] = kTag;
  }
}

// Peridigm's bond level and force (computeBondLevelUnrotatedRateOfDeformationAndRotationTensor,
// updateBondLevelElasticCauchyStress, computeBondLevelPiolaStress, computeStressIntegral, computeForce).
void BondAssociatedCorrespondenceMaterial::bondPhase(const FamilyView& fam, const double* y, StateStore& state,
                                                     const double* rows, int stride, double* force) const {
  BondTensor Vb(state, "Bond_Left_Stretch_Tensor", false), Rb(state, "Bond_Rotation_Tensor", false),
      taub(state, "Bond_Unrotated_Cauchy_Stress", true);
  const double* timeN = state.committed("Correspondence_Time");
  const bool history = law_->hasHistory();
  const double* epsN = history ? state.committed("Bond_Equivalent_Plastic_Strain") : nullptr;
  double* eps = history ? state.trial("Bond_Equivalent_Plastic_Strain") : nullptr;
  // Energies per node (J; only when an output asks): the bonds' weighted mean, shares omega V_j / w0_i (summing
  // to 1), of the stored J_b (1/2 tau_b : C^-1 : tau_b) and of the plastic work per step by the midpoint rule,
  // J_mid tau_mid : (de_b - C^-1 : (tau_b - tau_b,n)) (as the standard models' per node), times V_i.
  double* stored = storedWanted_ ? state.trial("Stored_Elastic_Energy") : nullptr;
  double* dissipated = dissipatedWanted_ ? state.trial("Dissipated_Energy") : nullptr;
  const double* dissipatedN = dissipatedWanted_ ? state.committed("Dissipated_Energy") : nullptr;
  const double* ref = fam.yN ? fam.yN : fam.x;
  std::vector<Mat3> P;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double* ri = rows + static_cast<std::size_t>(stride) * i;
    const Mat3 Fi = rowTensor(ri + kRowF), dFi = rowTensor(ri + kRowDF), Kinv = rowTensor(ri + kRowKinv);
    const double w0 = ri[kRowW0];
    const double step = bondAssociatedStepLength(fam, timeN, i);  // the law's dt (a rate-dependent law needs it)
    const double dt = fam.velocity ? step : 0.0;                     // scales the velocities to an increment
    const int first = fam.offsets[i], last = fam.offsets[i + 1];
    P.assign(static_cast<std::size_t>(last - first), Mat3{});
    Mat3 S{};
    double storedSum = 0.0, dissipatedSum = 0.0;
    for (int b = first; b < last; ++b) {
      const int j = fam.neighbors[b];
      const double* rj = rows + static_cast<std::size_t>(stride) * j;
      if (rj[kRowTag] != kTag)
        throw InputError(std::string(model_) + ": the point at " + pointAt(fam, i) +
                         " has a bond to a point of another material model; a bond-associated block shares bonds only "
                         "with blocks of the same model");
      const double w = bondWeight(fam, b);
      if (w == 0.0) {  // no bond (Peridigm: omega = 0 keeps the committed state)
        Vb.keep(b), Rb.keep(b), taub.keep(b);
        if (history) eps[b] = epsN[b];
        continue;
      }
      double xi[3], Y[3], dY[3];
      for (int a = 0; a < 3; ++a) {
        xi[a] = fam.x[3 * j + a] - fam.x[3 * i + a];
        Y[a] = y[3 * j + a] - y[3 * i + a];
        dY[a] = fam.velocity ? dt * (fam.velocity[3 * j + a] - fam.velocity[3 * i + a]) : Y[a] - (ref[3 * j + a] - ref[3 * i + a]);
      }
      const Mat3 F = bondGradient(Fi, rowTensor(rj + kRowF), xi, Y);
      const Mat3 dF = bondGradient(dFi, rowTensor(rj + kRowDF), xi, dY);
      const double J = det(F);
      if (!(J > 0.0)) {
        char buf[300];
        std::snprintf(buf, sizeof buf, "%s: det F = %.3g <= 0 for the bond from the point at %s to %s", model_, J,
                      pointAt(fam, i).c_str(), pointAt(fam, j).c_str());
        throw ConstitutiveFailure(buf);
      }
      const Mat3 VN = Vb.committedAt(b), tauN = taub.committedAt(b);
      const PolarUpdate pu = peridigmPolarUpdate(dF, F, Rb.committedAt(b), VN);
      double h = 0.0;
      const Mat3 tau = law_->update(tauN, history ? epsN[b] : 0.0, pu.dUnrot, step, h);
      if (history) eps[b] = h;
      if (stored) storedSum += w * J * hookeEnergyDensity(moduli_.bulk, moduli_.shear, tau);
      if (dissipated) {  // J_n = det V_n (det R = 1)
        const Mat3 dp = pu.dUnrot - hookeStrain(moduli_.bulk, moduli_.shear, tau - tauN);
        dissipatedSum += w * 0.5 * (J + det(VN)) * ddot(0.5 * (tau + tauN), dp);
      }
      Vb.set(b, pu.V), Rb.set(b, pu.R), taub.set(b, tau);
      P[b - first] = piolaFromUnrotated(F, pu.R, tau);
      const double wj = rj[kRowW0];
      S = S + (w * (0.5 / w0 + 0.5 / wj)) * mul(P[b - first], normalProjector(xi));
    }
    if (stored) stored[i] = w0 > 0.0 ? fam.volume[i] * storedSum / w0 : 0.0;
    if (dissipated) dissipated[i] = dissipatedN[i] + (w0 > 0.0 ? fam.volume[i] * dissipatedSum / w0 : 0.0);
    addBondForces(fam, i, P, S, Kinv, w0, force);
  }
}

// f_i += T V_j, f_j -= T V_i for each bond of node i with its Piola stress P[b - first] and the node's S, K^-1, w0.
void BondAssociatedCorrespondenceMaterial::addBondForces(const FamilyView& fam, int i, const std::vector<Mat3>& P,
                                                         const Mat3& S, const Mat3& Kinv, double w0, double* force) {
  const int first = fam.offsets[i];
  for (int b = first; b < fam.offsets[i + 1]; ++b) {
    if (bondWeight(fam, b) == 0.0) continue;
    const int j = fam.neighbors[b];
    const double frac = fam.fraction ? fam.fraction[b] : 1.0;
    double xi[3], T[3];
    for (int a = 0; a < 3; ++a) xi[a] = fam.x[3 * j + a] - fam.x[3 * i + a];
    bondForceState(P[b - first], S, Kinv, xi, fam.unitInfluence ? 1.0 : fam.influence[b], w0, T);
    for (int a = 0; a < 3; ++a) {
      force[3 * i + a] += T[a] * fam.volume[j] * frac;
      force[3 * j + a] -= T[a] * fam.volume[i] * frac;
    }
  }
}

void BondAssociatedCorrespondenceMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  bondAssociatedStiffnessBound(fam, std::max(3.0 * moduli_.bulk, 2.0 * moduli_.shear), bound);
}

void BondAssociatedCorrespondenceMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  bondAssociatedPairStiffness(fam, moduli_.bulk, c);
}

}  // namespace pf
