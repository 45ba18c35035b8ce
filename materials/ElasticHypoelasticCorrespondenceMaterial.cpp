#include "ElasticHypoelasticCorrespondenceMaterial.hpp"

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

const char* const kModel = "Elastic Hypoelastic Correspondence";
const double kTag = 11.0;  // marks a row written by this model


// The motion the rate is taken from: the velocities where the solver gives them (then the gradient is L and
// L dt = dt L), else the step's displacement from the committed positions (the gradient is L dt itself).
struct Motion {
  const double* v;  // 3 per overlap node
  const double* y;
  const double* ref;
  double at(int j, int a) const { return v ? v[3 * j + a] : y[3 * j + a] - ref[3 * j + a]; }
};
Motion motionOf(const FamilyView& fam, const double* y) { return {fam.velocity, y, fam.yN ? fam.yN : fam.x}; }

double partialVolume(const FamilyView& fam, int b) { return fam.fraction ? fam.fraction[b] : 1.0; }

}  // namespace

ElasticHypoelasticCorrespondenceMaterial::ElasticHypoelasticCorrespondenceMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")) {
  requireFirstOrderGradients(in);
}

MaterialEntry ElasticHypoelasticCorrespondenceMaterial::entry() {
  using P = ParameterSpec;
  return {kModel,
          "semi-Lagrangian bond-associated hypoelastic correspondence solid: gradients on the current configuration, "
          "a rotation and stress per bond (Peridigm; Behzadinasab & Foster)",
          [] {
            auto p = bondAssociatedParameters();
            p.push_back(P::real("Actual Horizon",
                                "Peridigm's horizon of the influence function on deformed bonds (the block's Horizon "
                                "only builds the neighbour lists); with the influence function One, the only one "
                                "taken, it changes nothing")
                            .need().positive());
            return p;
          }(),
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticHypoelasticCorrespondenceMaterial(in)); },
          bondAssociatedOutputs({"Jacobian_Determinant"}, {"Velocity_Gradient"})};
}

std::vector<StateSpec> ElasticHypoelasticCorrespondenceMaterial::stateSpecs() const {
  std::vector<StateSpec> s;
  addBondAssociatedSpecs(s);
  addTensorSpecs(s, "Velocity_Gradient", false, true, false, false);
  s.push_back({"Jacobian_Determinant", Location::Node, true, true, 1.0});
  return s;
}

void ElasticHypoelasticCorrespondenceMaterial::enableOutput(const std::string& name) const {
  if (name.rfind("Cauchy_Stress", 0) == 0) cauchyWanted_ = true;
  if (name.rfind("Unrotated_Rate_Of_Deformation", 0) == 0) rateWanted_ = true;
}

Mat3 ElasticHypoelasticCorrespondenceMaterial::elasticIncrement(const Mat3& de) const {
  return hookeIncrement(moduli_.bulk, moduli_.shear, de);
}

void ElasticHypoelasticCorrespondenceMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                            double* force) const {
  if (!fam.unitInfluence)
    throw InputError(std::string(kModel) + ": 'Influence Function' must be One (every omega = 1): Peridigm evaluates "
                     "omega on the deformed bond with 'Actual Horizon', which is not implemented");
  if (fam.exchange) {
    jacobianPhase(fam, state, fam.exchange, fam.exchangeStride);
    return;
  }
  std::vector<double> rows(static_cast<std::size_t>(fam.numNodes) * kRow, 0.0);
  jacobianPhase(fam, state, rows.data(), kRow);
  nodePhase(fam, y, state, rows.data(), kRow);
  bondPhase(fam, y, state, rows.data(), kRow, force);
}

void ElasticHypoelasticCorrespondenceMaterial::completeForce(const FamilyView& fam, const double* y, StateStore& state,
                                                             double* force) const {
  if (fam.exchangeRound == 0)
    nodePhase(fam, y, state, fam.exchange, fam.exchangeStride);
  else
    bondPhase(fam, y, state, fam.exchange, fam.exchangeStride, force);
}

void ElasticHypoelasticCorrespondenceMaterial::jacobianPhase(const FamilyView& fam, StateStore& state, double* rows,
                                                             int stride) const {
  const double* JN = state.committed("Jacobian_Determinant");
  double* time = state.trial("Correspondence_Time");
  for (int i = fam.begin; i < fam.end; ++i) {
    double* row = rows + static_cast<std::size_t>(stride) * i;
    row[kRowJ] = JN[i];
    row[kRowTag] = kTag;
    time[i] = fam.time;
  }
}

// Peridigm's precompute (computeGradientWeights, computeVelocityGradient, computeUndamagedWeightedVolume) and node
// level (updateDeformationGradient, computeNodeLevelUnrotatedRateOfDeformationAndRotationTensor, the elastic update):
// outputs, and the rows the bonds need.
void ElasticHypoelasticCorrespondenceMaterial::nodePhase(const FamilyView& fam, const double* y, StateStore& state,
                                                         double* rows, int stride) const {
  TensorField Fs(state, "Deformation_Gradient", false), Rs(state, "Rotation_Tensor", false),
      Vs(state, "Left_Stretch_Tensor", false), taus(state, "Unrotated_Cauchy_Stress", true),
      Ls(state, "Velocity_Gradient", false);
  const double* JN = state.committed("Jacobian_Determinant");
  double* J = state.trial("Jacobian_Determinant");
  double* vm = state.trial("Von_Mises_Stress");
  const double* timeN = state.committed("Correspondence_Time");
  // The optional outputs: the fields always exist, written only when an output asks (enableOutput).
  TensorField rate(state, "Unrotated_Rate_Of_Deformation", true), cauchy(state, "Cauchy_Stress", true);
  const Motion m = motionOf(fam, y);
  for (int i = fam.begin; i < fam.end; ++i) {
    const double dt = bondAssociatedStepLength(fam, timeN, i);
    Mat3 M{};
    double w0 = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double* rj = rows + static_cast<std::size_t>(stride) * j;
      if (rj[kRowTag] != kTag)
        throw InputError(std::string(kModel) + ": the point at " + pointAt(fam, i) +
                         " has a bond to a point of another material model; this model shares bonds only with blocks "
                         "of the same model");
      const double w = rj[kRowJ] * fam.volume[j] * partialVolume(fam, b);  // omega = 1
      double Y[3];
      for (int a = 0; a < 3; ++a) Y[a] = y[3 * j + a] - y[3 * i + a];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) M[3 * a + c] += w * Y[a] * Y[c];
      w0 += w;
    }
    Mat3 Minv;
    const double scale = trace(M) / 3.0;
    if (!(inverse(M, Minv) > 1e-12 * scale * scale * scale))
      throw ConstitutiveFailure(std::string(kModel) + ": the moment matrix of the point at " + pointAt(fam, i) +
                                " is singular on the deformed bonds (fewer than three non-coplanar bonds)");
    Mat3 G{};  // L (velocities) or L dt (the step's displacement)
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = rows[static_cast<std::size_t>(stride) * j + kRowJ] * fam.volume[j] * partialVolume(fam, b);
      double Y[3], phi[3];
      for (int a = 0; a < 3; ++a) Y[a] = y[3 * j + a] - y[3 * i + a];
      for (int a = 0; a < 3; ++a) phi[a] = Minv[3 * a] * Y[0] + Minv[3 * a + 1] * Y[1] + Minv[3 * a + 2] * Y[2];
      for (int a = 0; a < 3; ++a) {
        const double dv = m.at(j, a) - m.at(i, a);
        for (int c = 0; c < 3; ++c) G[3 * a + c] += dv * phi[c] * w;
      }
    }
    const Mat3 Ldt = m.v ? dt * G : G;
    const Mat3 L = m.v ? G : (dt > 0.0 ? (1.0 / dt) * G : Mat3{});
    J[i] = JN[i] * (1.0 + trace(Ldt));
    Fs.set(i, Fs.committedAt(i) + mul(Ldt, Fs.committedAt(i)));
    Ls.set(i, L);
    const PolarUpdate pu = peridigmPolarUpdate(Ldt, identity3(), Rs.committedAt(i), Vs.committedAt(i));
    const Mat3 tau = taus.committedAt(i) + elasticIncrement(pu.dUnrot);
    Rs.set(i, pu.R), Vs.set(i, pu.V), taus.set(i, tau);
    vm[i] = vonMises(tau);
    if (rateWanted_) rate.set(i, dt > 0.0 ? (1.0 / dt) * pu.dUnrot : rate.committedAt(i));
    if (cauchyWanted_) cauchy.set(i, mul(pu.R, mulNT(tau, pu.R)));
    double* row = rows + static_cast<std::size_t>(stride) * i;
    std::copy(Ldt.begin(), Ldt.end(), row + kRowLdt);
    std::copy(Minv.begin(), Minv.end(), row + kRowMinv);
    row[kRowW0] = w0;
  }
}

// Peridigm's computeBondLevelVelocityGradient, bond-level rotation and stress, computeNonhomogeneityIntegral and
// computeForce.
void ElasticHypoelasticCorrespondenceMaterial::bondPhase(const FamilyView& fam, const double* y, StateStore& state,
                                                         const double* rows, int stride, double* force) const {
  BondTensor Vb(state, "Bond_Left_Stretch_Tensor", false), Rb(state, "Bond_Rotation_Tensor", false),
      taub(state, "Bond_Unrotated_Cauchy_Stress", true);
  const double* timeN = state.committed("Correspondence_Time");
  const Motion m = motionOf(fam, y);
  std::vector<Mat3> sigma;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double* ri = rows + static_cast<std::size_t>(stride) * i;
    const Mat3 Ldti = rowTensor(ri + kRowLdt), Minv = rowTensor(ri + kRowMinv);
    const double w0 = ri[kRowW0], Ji = ri[kRowJ];
    const double scale = m.v ? bondAssociatedStepLength(fam, timeN, i) : 1.0;  // velocity difference -> its increment
    const int first = fam.offsets[i], last = fam.offsets[i + 1];
    sigma.assign(static_cast<std::size_t>(last - first), Mat3{});
    Mat3 S{};
    for (int b = first; b < last; ++b) {
      const int j = fam.neighbors[b];
      const double* rj = rows + static_cast<std::size_t>(stride) * j;
      double Y[3], dV[3];
      for (int a = 0; a < 3; ++a) Y[a] = y[3 * j + a] - y[3 * i + a], dV[a] = scale * (m.at(j, a) - m.at(i, a));
      const Mat3 Lbdt = bondGradient(Ldti, rowTensor(rj + kRowLdt), Y, dV);
      const PolarUpdate pu = peridigmPolarUpdate(Lbdt, identity3(), Rb.committedAt(b), Vb.committedAt(b));
      const Mat3 tau = taub.committedAt(b) + elasticIncrement(pu.dUnrot);
      Vb.set(b, pu.V), Rb.set(b, pu.R), taub.set(b, tau);
      sigma[b - first] = mul(pu.R, mulNT(tau, pu.R));
      const double w = rj[kRowJ] * fam.volume[j] * partialVolume(fam, b);
      S = S + (w * (0.5 / w0 + 0.5 / rj[kRowW0])) * mul(sigma[b - first], normalProjector(Y));
    }
    for (int b = first; b < last; ++b) {
      const int j = fam.neighbors[b];
      const double Jj = rows[static_cast<std::size_t>(stride) * j + kRowJ], frac = partialVolume(fam, b);
      double Y[3], T[3];
      for (int a = 0; a < 3; ++a) Y[a] = y[3 * j + a] - y[3 * i + a];
      bondForceState(sigma[b - first], S, Minv, Y, 1.0, w0, T);
      for (int a = 0; a < 3; ++a) {
        force[3 * i + a] += Ji * T[a] * Jj * fam.volume[j] * frac;
        force[3 * j + a] -= Jj * T[a] * Ji * fam.volume[i] * frac;
      }
    }
  }
}

void ElasticHypoelasticCorrespondenceMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  bondAssociatedStiffnessBound(fam, std::max(3.0 * moduli_.bulk, 2.0 * moduli_.shear), bound);
}

void ElasticHypoelasticCorrespondenceMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  bondAssociatedPairStiffness(fam, moduli_.bulk, c);
}

}  // namespace pf
