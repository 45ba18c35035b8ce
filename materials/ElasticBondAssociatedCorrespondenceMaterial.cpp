#include "ElasticBondAssociatedCorrespondenceMaterial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "BondAssociatedKinematics.hpp"
#include "BondAssociatedCommon.hpp"
#include "BondTensorFields.hpp"
#include "CorrespondenceKinematics.hpp"
#include "core/InputError.hpp"

namespace pf {
namespace {

const char* const kModel = "Elastic Bond Associated Correspondence";
const double kTag = 7.0;  // marks a row written by this model (a neighbour of another model leaves 0)

}  // namespace

ElasticBondAssociatedCorrespondenceMaterial::ElasticBondAssociatedCorrespondenceMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")) {
  requireFirstOrderGradients(in);
}

MaterialEntry ElasticBondAssociatedCorrespondenceMaterial::entry() {
  return {kModel,
          "bond-associated hypoelastic correspondence solid: a deformation gradient, rotation and stress per bond, no "
          "hourglass force (Peridigm; Chen & Spencer 2019)",
          bondAssociatedParameters(),
          [](const MaterialInput& in) {
            return std::unique_ptr<Material>(new ElasticBondAssociatedCorrespondenceMaterial(in));
          },
          bondAssociatedOutputs({}, {})};
}

std::vector<StateSpec> ElasticBondAssociatedCorrespondenceMaterial::stateSpecs() const {
  std::vector<StateSpec> s;
  addBondAssociatedSpecs(s);
  return s;
}

void ElasticBondAssociatedCorrespondenceMaterial::enableOutput(const std::string& name) const {
  if (name.rfind("Cauchy_Stress", 0) == 0) cauchyWanted_ = true;
  if (name.rfind("Unrotated_Rate_Of_Deformation", 0) == 0) rateWanted_ = true;
}

Mat3 ElasticBondAssociatedCorrespondenceMaterial::elasticIncrement(const Mat3& de) const {
  return hookeIncrement(moduli_.bulk, moduli_.shear, de);
}

void ElasticBondAssociatedCorrespondenceMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                               double* force) const {
  if (fam.exchange) {
    nodePhase(fam, y, state, fam.exchange, fam.exchangeStride);
    return;
  }
  std::vector<double> rows(static_cast<std::size_t>(fam.numNodes) * kRow, 0.0);
  nodePhase(fam, y, state, rows.data(), kRow);
  bondPhase(fam, y, state, rows.data(), kRow, force);
}

void ElasticBondAssociatedCorrespondenceMaterial::completeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                                double* force) const {
  bondPhase(fam, y, state, fam.exchange, fam.exchangeStride, force);
}

// Peridigm's node level (computeNodeLevelUnrotatedRateOfDeformationAndRotationTensor, updateElasticCauchyStress):
// F from the first-order gradient weights (= the shape-tensor gradient), F-dot dt from the velocities (or the step's
// increment), the first-order polar update, tau = tau_n + C : d dt. These are outputs only; the force uses the bonds'.
void ElasticBondAssociatedCorrespondenceMaterial::nodePhase(const FamilyView& fam, const double* y, StateStore& state,
                                                            double* rows, int stride) const {
  TensorField Fs(state, "Deformation_Gradient", false), Rs(state, "Rotation_Tensor", false),
      Vs(state, "Left_Stretch_Tensor", false), taus(state, "Unrotated_Cauchy_Stress", true);
  double* vm = state.trial("Von_Mises_Stress");
  const double* timeN = state.committed("Correspondence_Time");
  // The optional outputs: the fields always exist, written only when an output asks (enableOutput).
  TensorField rate(state, "Unrotated_Rate_Of_Deformation", true), cauchy(state, "Cauchy_Stress", true);
  double* time = state.trial("Correspondence_Time");
  const double* ref = fam.yN ? fam.yN : fam.x;  // the committed positions (the reference before the first commit)
  for (int i = fam.begin; i < fam.end; ++i) {
    const double dt = bondAssociatedStepLength(fam, timeN, i);
    time[i] = fam.time;
    const ShapeAndGradient sg = shapeAndGradient(fam, i, y, false);
    requirePositiveJacobian(fam, i, y, sg.F);
    const Mat3 dF = fam.velocity ? dt * velocityGradient(fam, i, fam.velocity, sg.Kinv, false)
                                 : sg.F - mul(familySums(fam, i, ref, false).N, sg.Kinv);
    const PolarUpdate pu = peridigmPolarUpdate(dF, sg.F, Rs.committedAt(i), Vs.committedAt(i));
    const Mat3 tau = taus.committedAt(i) + elasticIncrement(pu.dUnrot);
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
void ElasticBondAssociatedCorrespondenceMaterial::bondPhase(const FamilyView& fam, const double* y, StateStore& state,
                                                            const double* rows, int stride, double* force) const {
  BondTensor Vb(state, "Bond_Left_Stretch_Tensor", false), Rb(state, "Bond_Rotation_Tensor", false),
      taub(state, "Bond_Unrotated_Cauchy_Stress", true);
  const double* timeN = state.committed("Correspondence_Time");
  const double* ref = fam.yN ? fam.yN : fam.x;
  std::vector<Mat3> P;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double* ri = rows + static_cast<std::size_t>(stride) * i;
    const Mat3 Fi = rowTensor(ri + kRowF), dFi = rowTensor(ri + kRowDF), Kinv = rowTensor(ri + kRowKinv);
    const double w0 = ri[kRowW0];
    const double dt = fam.velocity ? bondAssociatedStepLength(fam, timeN, i) : 0.0;
    const int first = fam.offsets[i], last = fam.offsets[i + 1];
    P.assign(static_cast<std::size_t>(last - first), Mat3{});
    Mat3 S{};
    for (int b = first; b < last; ++b) {
      const int j = fam.neighbors[b];
      const double* rj = rows + static_cast<std::size_t>(stride) * j;
      if (rj[kRowTag] != kTag)
        throw InputError(std::string(kModel) + ": the point at " + pointAt(fam, i) +
                         " has a bond to a point of another material model; a bond-associated block shares bonds only "
                         "with blocks of the same model");
      const double w = bondWeight(fam, b);
      if (w == 0.0) {  // no bond (Peridigm: omega = 0 keeps the committed state)
        Vb.keep(b), Rb.keep(b), taub.keep(b);
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
      if (!(det(F) > 0.0)) {
        char buf[300];
        std::snprintf(buf, sizeof buf, "%s: det F = %.3g <= 0 for the bond from the point at %s to %s", kModel, det(F),
                      pointAt(fam, i).c_str(), pointAt(fam, j).c_str());
        throw ConstitutiveFailure(buf);
      }
      const PolarUpdate pu = peridigmPolarUpdate(dF, F, Rb.committedAt(b), Vb.committedAt(b));
      const Mat3 tau = taub.committedAt(b) + elasticIncrement(pu.dUnrot);
      Vb.set(b, pu.V), Rb.set(b, pu.R), taub.set(b, tau);
      P[b - first] = piolaFromUnrotated(F, pu.R, tau);
      const double wj = rj[kRowW0];
      S = S + (w * (0.5 / w0 + 0.5 / wj)) * mul(P[b - first], normalProjector(xi));
    }
    for (int b = first; b < last; ++b) {
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
}

void ElasticBondAssociatedCorrespondenceMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  bondAssociatedStiffnessBound(fam, std::max(3.0 * moduli_.bulk, 2.0 * moduli_.shear), bound);
}

void ElasticBondAssociatedCorrespondenceMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  bondAssociatedPairStiffness(fam, moduli_.bulk, c);
}

}  // namespace pf
