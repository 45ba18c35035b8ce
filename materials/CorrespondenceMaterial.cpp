#include "CorrespondenceMaterial.hpp"

#include <algorithm>
#include <cmath>

#include "CorrespondenceFields.hpp"
#include "CorrespondenceKinematics.hpp"
#include "UnrotatedHooke.hpp"
#include "SolidParameters.hpp"
#include "core/InputError.hpp"
#include "core/StressDamage.hpp"

namespace pf {
namespace {

const double kPi = 3.14159265358979323846;

// 3D, or Plane Strain with a Thickness. No Plane Stress: its out-of-plane stretch would have to come from
// the stress update's zero-stress condition; the parameter is not taken, so a deck with it is refused.
Dimension correspondenceDimension(const MaterialInput& in, const std::string& model, double* thickness) {
  const std::string where = in.inputFile + ": material '" + in.name + "' (" + model + ")";
  if (!in.flag("Plane Strain")) {
    if (in.has("Thickness")) throw InputError(where + ": 'Thickness' is only for Plane Strain");
    *thickness = 0.0;
    return Dimension::ThreeD;
  }
  if (!in.has("Thickness")) throw InputError(where + ": 'Thickness' is needed by Plane Strain");
  *thickness = in.get("Thickness");
  return Dimension::PlaneStrain;
}

// The trial and committed kinematic state of a block's nodes.
struct KinematicFields {
  TensorField F, R, V;
  explicit KinematicFields(StateStore& s)
      : F(s, "Deformation_Gradient", false), R(s, "Rotation_Tensor", false), V(s, "Left_Stretch_Tensor", false) {}
};

struct NodeKinematics {
  Mat3 Kinv, F, R, de;
};

// Phase 1 of computeForce for owned node i: K^-1, F and the polar update (trial F, R, V written), dt the time since
// the node's last commit. Stress damage (core/StressDamage.hpp): K and F leave out the bonds broken in fam.brokenN
// (omega' = 0); a point whose intact bonds no longer span the space (singular K) is detached: no increment, so its
// update is trivial. Returns false for such a point.
bool nodeKinematics(const FamilyView& fam, int i, const double* y, KinematicFields& ks, bool planar, bool endOfStep,
                    double dt, NodeKinematics& out) {
  ShapeAndGradient sg;
  bool attached = true;
  if (!(fam.brokenN && fam.tensileStrength > 0.0))
    sg = shapeAndGradient(fam, i, y, planar);
  else if (!tryShapeAndGradient(fam, i, y, planar, sg))
    attached = false, sg.Kinv = Mat3{}, sg.F = ks.F.committedAt(i);
  if (attached) requirePositiveJacobian(fam, i, y, sg.F);
  const Mat3 Fn = ks.F.committedAt(i), Rn = ks.R.committedAt(i), Vn = ks.V.committedAt(i);
  PolarUpdate pu;
  if (!endOfStep)
    pu = flanaganTaylor(Fn, sg.F, Rn, Vn);
  else  // Peridigm's Fdot dt: the velocity-state gradient where the solver gives velocities, else the step's F - F_n
    pu = peridigmPolarUpdate(fam.velocity ? dt * velocityGradient(fam, i, fam.velocity, sg.Kinv, planar) : sg.F - Fn,
                             sg.F, Rn, Vn);
  out.Kinv = sg.Kinv, out.F = sg.F, out.R = pu.R, out.de = pu.dUnrot;
  ks.F.set(i, sg.F), ks.R.set(i, pu.R), ks.V.set(i, pu.V);
  return attached;
}

}  // namespace

CorrespondenceMaterial::CorrespondenceMaterial(const MaterialInput& in, const std::string& model)
    : moduli_(elasticModuliFrom(in)), dim_(correspondenceDimension(in, model, &thickness_)),
      density_(in.get("Density")), hourglass_(in.get("Hourglass Coefficient")),
      alpha_(in.get("Thermal Expansion Coefficient", 0.0)), endOfStep_(in.text("Rate Of Deformation") == "End Of Step") {}

std::vector<std::string> CorrespondenceMaterial::fieldsRead() const {
  if (alpha_ == 0.0) return {};
  return {"Temperature_Change"};
}

void CorrespondenceMaterial::subtractThermalIncrement(const FamilyView& fam, const StateStore& state,
                                                      std::vector<Mat3>& de) const {
  const double* dT = fam.fields->find("Temperature_Change");  // trial, per overlap node (owned first)
  const double* dTn = state.committed("Temperature_Change");   // per owned node
  for (std::size_t k = 0; k < de.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    const double d = alpha_ * (dT[i] - dTn[i]) / (endOfStep_ ? 1.0 : 1.0 + 0.5 * alpha_ * (dT[i] + dTn[i]));
    de[k][0] -= d, de[k][4] -= d, de[k][8] -= d;
  }
}

std::vector<ParameterSpec> CorrespondenceMaterial::commonParameters(RateRule byDefault) {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = {
      P::real("Density", "mass density [kg/m^3]").need().positive(),
      P::real("Bulk Modulus", "give exactly two of the four elastic constants").positive(),
      P::real("Shear Modulus").positive(),
      P::real("Young's Modulus").positive(),
      P::real("Poisson's Ratio").above(-1.0).below(0.5),
      P::flag("Plane Strain", "2D plane-strain model (points in z = 0, needs Thickness)").byDefault("false"),
      P::real("Thickness", "out-of-plane thickness of a 2D model [m]").positive(),
      P::real("Hourglass Coefficient",
              "weight of the zero-energy-mode force, times the bond-based micromodulus (Peridigm)").need().nonNegative(),
      P::real("Thermal Expansion Coefficient",
              "linear thermal expansion coefficient alpha [1/K]: the thermal stretch (1 + alpha dT) I leaves the "
              "rate of deformation before the stress update (docs/thermal.md); reads the Temperature field"),
      P::text("Rate Of Deformation",
              "'End Of Step': Peridigm's rate, L = Fdot F^-1 at the step's end (Fdot from the velocities under Verlet, "
              "(F - F_n)/dt otherwise), its first-order polar update and thermal increment; 'Midpoint': Periforge's, "
              "(F - F_n) F_mid^-1/dt with the second-order Flanagan-Taylor update (a rigid rotation never stresses, "
              "(1 + alpha dT) I is stress-free). Default: 'End Of Step' for Peridigm's models (Elastic, Elastic "
              "Plastic, Isotropic Hardening, Viscoplastic Needleman Correspondence), 'Midpoint' for Viscoplastic "
              "and Drucker Prager Correspondence (docs/materials.md)")
          .oneOf({"End Of Step", "Midpoint"})
          .byDefault(byDefault == RateRule::EndOfStep ? "End Of Step" : "Midpoint"),
  };
  for (ParameterSpec& p : heatParameters(true)) params.push_back(std::move(p));
  return params;
}

std::vector<std::unique_ptr<FieldOperator>> CorrespondenceMaterial::heatTerms(const MaterialInput& in,
                                                                             const std::string& model) {
  double thickness = 0.0;
  const Dimension dim = correspondenceDimension(in, model, &thickness);
  return heatTermsOf(in, dim, thickness);
}

std::vector<std::string> CorrespondenceMaterial::commonOutputs() {
  std::vector<std::string> out;
  for (const char* base : {"Unrotated_Cauchy_Stress", "Cauchy_Stress", "Unrotated_Rate_Of_Deformation"})
    for (const char* c : kSym) out.push_back(std::string(base) + c);
  out.push_back("Von_Mises_Stress");
  for (const char* base : {"Deformation_Gradient", "Rotation_Tensor", "Left_Stretch_Tensor"})
    for (const char* c : kFull) out.push_back(std::string(base) + c);
  for (const char* c : {"X", "Y", "Z"}) out.push_back(std::string("Hourglass_Force_Density") + c);
  out.push_back("Stored_Elastic_Energy");
  out.push_back("Dissipated_Energy");
  return out;
}

std::vector<StateSpec> CorrespondenceMaterial::stateSpecs() const {
  std::vector<StateSpec> s;
  addTensorSpecs(s, "Unrotated_Cauchy_Stress", true, true, false);
  addTensorSpecs(s, "Deformation_Gradient", false, true, true);
  addTensorSpecs(s, "Rotation_Tensor", false, true, true);
  addTensorSpecs(s, "Left_Stretch_Tensor", false, true, true);
  s.push_back({"Von_Mises_Stress", Location::Node, false, true});
  s.push_back({"Stored_Elastic_Energy", Location::Node, false, true});
  s.push_back({"Dissipated_Energy", Location::Node, true, true});
  s.push_back({"Hourglass_Work", Location::Node, true, false});  // part of Stored_Elastic_Energy
  for (const StateSpec& m : outputStateSpecs()) s.push_back(m);
  for (const StateSpec& m : modelStateSpecs()) s.push_back(m);
  return s;
}

double CorrespondenceMaterial::micromodulus(double horizon) const {
  const double d = horizon;
  if (dim_ == Dimension::ThreeD) return 18.0 * moduli_.bulk / (kPi * d * d * d * d);
  const double k2 = moduli_.bulk + moduli_.shear / 3.0;
  return 12.0 * k2 / (kPi * thickness_ * d * d * d);
}

double CorrespondenceMaterial::hourglassConstant(double horizon) const { return hourglass_ * micromodulus(horizon); }

void CorrespondenceMaterial::enableOutput(const std::string& name) const {
  if (name == "Stored_Elastic_Energy") storedWanted_ = true;
  if (name == "Dissipated_Energy") dissipatedWanted_ = true;
  enableTensorOutput(name);
}

double CorrespondenceMaterial::elasticEnergyDensity(const Mat3& tau) const {
  return hookeEnergyDensity(moduli_.bulk, moduli_.shear, tau);
}

Mat3 CorrespondenceMaterial::elasticStrain(const Mat3& dtau) const { return hookeStrain(moduli_.bulk, moduli_.shear, dtau); }

Mat3 CorrespondenceMaterial::elasticIncrement(const Mat3& de) const {
  return hookeIncrement(moduli_.bulk, moduli_.shear, de);
}

std::vector<double> CorrespondenceMaterial::stepLengths(const FamilyView& fam, StateStore& state) const {
  const double* timeN = state.committed("Correspondence_Time");
  double* time = state.trial("Correspondence_Time");
  std::vector<double> dt(static_cast<std::size_t>(fam.end - fam.begin));
  for (int i = fam.begin; i < fam.end; ++i) {
    dt[i - fam.begin] = fam.time - (std::isnan(timeN[i]) ? fam.startTime : timeN[i]);
    time[i] = fam.time;
  }
  return dt;
}

namespace {

// Whether owned node i sums its force in gather form: every neighbour has i's horizon, so each bond of i's family is
// also a bond of the neighbour's, with the same omega and partial volume. Otherwise (horizons that differ along a
// bond: the families are not symmetric) i adds its own bonds one-pass, f_i += T V_j, f_j -= T V_i, as Peridigm does
// for every point; the neighbours see its zero row and do the same for their bonds to i.
bool gathers(const FamilyView& fam, int i) {
  if (!fam.pointHorizon) return true;
  const double h = fam.pointHorizon[i];
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
    if (fam.pointHorizon[fam.neighbors[b]] != h) return false;
  return true;
}

}  // namespace

void CorrespondenceMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                          double* force) const {
  KinematicFields ks(state);
  const TensorField& Fs = ks.F;
  TensorField taus(state, "Unrotated_Cauchy_Stress", true);
  double* vm = state.trial("Von_Mises_Stress");
  const int n = fam.end - fam.begin;
  std::vector<Mat3> Kinv(n), F(n), R(n), tauN(n), de(n), tau(n);
  std::vector<double> Jn(dissipatedWanted_ ? n : 0);
  // A point detached by stress damage has no stress and no hourglass term of its own, and sigma1 = +inf in its row
  // so that its remaining bonds break at the next decision.
  const bool stressDamage = fam.brokenN && fam.tensileStrength > 0.0;
  std::vector<char> detached(stressDamage ? n : 0, 0);
  const std::vector<double> dt = stepLengths(fam, state);
  // Phase 1: kinematics of every owned node, from its own family.
  for (int k = 0; k < n; ++k) {
    const int i = fam.begin + k;
    if (dissipatedWanted_) Jn[k] = det(Fs.committedAt(i));
    NodeKinematics nk;
    if (!nodeKinematics(fam, i, y, ks, isPlanar(dim_), endOfStep_, dt[k], nk)) detached[k] = 1;
    Kinv[k] = nk.Kinv, F[k] = nk.F, R[k] = nk.R, de[k] = nk.de, tauN[k] = taus.committedAt(i);
  }
  // Phase 2: the model's stress update on the mechanical increment; phase 3: stress to force state, plus the
  // hourglass force.
  stressUpdate(fam, state, R, dt, tauN, de, tau);
  // Energies per node (J; docs/materials.md, "Energy"). Foster et al. (2010)'s Eqs. 49-52 are rate forms of
  // Cauchy stress: the stress power per reference volume is J sigma : D = J tau : d (Eq. 18's unrotated d).
  // Stored: J V (1/2 tau : C^-1 : tau) plus the work taken by the hourglass bonds (history, trapezoid rule).
  // Dissipated: the plastic work, per step by the midpoint rule, J_mid V tau_mid : (de - C^-1 : (tau - tau_n)),
  // zero for an elastic step.
  double* stored = storedWanted_ ? state.trial("Stored_Elastic_Energy") : nullptr;
  double* hgWork = storedWanted_ ? state.trial("Hourglass_Work") : nullptr;
  const double* hgWorkN = storedWanted_ ? state.committed("Hourglass_Work") : nullptr;
  double* dissipated = dissipatedWanted_ ? state.trial("Dissipated_Energy") : nullptr;
  const double* dissipatedN = dissipatedWanted_ ? state.committed("Dissipated_Energy") : nullptr;
  for (int k = 0; k < n; ++k) {
    const int i = fam.begin + k;
    const double c = hourglassConstant(horizonAt(fam, i));  // Peridigm: the point's own horizon
    if (stressDamage && detached[k]) tau[k] = Mat3{};
    taus.set(i, tau[k]);
    vm[i] = vonMises(tau[k]);
    const Mat3 P = piolaFromUnrotated(F[k], R[k], tau[k]);
    const Mat3 A = mul(P, Kinv[k]);
    if (fam.exchange && gathers(fam, i)) {  // gather form: completeForce adds it once every row is on the ghosts
      double* row = fam.exchange + static_cast<std::size_t>(fam.exchangeStride) * i;
      std::copy(A.begin(), A.end(), row + kRowA);
      std::copy(F[k].begin(), F[k].end(), row + kRowF);
      row[kRowC] = stressDamage && detached[k] ? 0.0 : c;
      row[kRowFlag] = 1.0;
      // sigma1 always (a few flops per point): a damaged block's bond to a point of an undamaged correspondence block
      // then sees that point's true sigma1 (a one-pass model's zero row gives 0).
      double t6[6];
      toSym6(tau[k], t6);
      row[kRowS1] = stressDamage && detached[k] ? HUGE_VAL : maxPrincipal(t6);
      if (fam.band) {
        std::copy(P.begin(), P.end(), row + kRowP);
        std::copy(Kinv[k].begin(), Kinv[k].end(), row + kRowKinv);
      }
    } else {  // one-pass; in a model run its zero row tells the neighbours' gather sums to send it their reactions
      addCorrespondenceForce(fam, i, A, force);
      addHourglassForce(fam, i, y, F[k], c, force);
    }
    if (stored) {
      // No committed positions yet (the run's first evaluation): no step, no work.
      hgWork[i] = hgWorkN[i] + (fam.yN ? hourglassWork(fam, i, fam.yN, Fs.committedAt(i), y, F[k], c) : 0.0);
      stored[i] = det(F[k]) * fam.volume[i] * elasticEnergyDensity(tau[k]) + hgWork[i];
    }
    if (dissipated) {
      const Mat3 dp = de[k] - elasticStrain(tau[k] - tauN[k]);
      const double Jmid = 0.5 * (Jn[k] + det(F[k]));
      dissipated[i] = dissipatedN[i] + Jmid * fam.volume[i] * ddot(0.5 * (tau[k] + tauN[k]), dp);
    }
  }
}

// The optional outputs around the model's update: the rate before the thermal part leaves d (Peridigm's field is the
// whole rate), the Cauchy stress after.
void CorrespondenceMaterial::stressUpdate(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& R,
                                          const std::vector<double>& dt, const std::vector<Mat3>& tauN,
                                          std::vector<Mat3>& de, std::vector<Mat3>& tau) const {
  writeRateOfDeformation(fam, state, de, dt);
  if (alpha_ != 0.0) subtractThermalIncrement(fam, state, de);
  updateStress(fam, state, tauN, de, dt, tau);
  writeCauchyStress(fam, state, R, tau);
}

int CorrespondenceMaterial::exchangeWidth(const FamilyView& fam) const { return fam.band ? kBandRow : kGatherRow; }

// With the Maximum Principal Stress damage model (fam.tensileStrength > 0) each owned node first decides its
// bonds from both ends' sigma1 in the rows (the owner of each end decides its half-bond from the same two numbers,
// so the two halves agree at any rank count), writes every trial flag, its count and Damage (Eq. 51), and then
// sums its force without the broken bonds. The shape tensors of this evaluation left out only the base set's
// bonds (fam.brokenN): a bond broken now leaves K and F from the next evaluation on (quasi-static: the break
// rounds solve the step again with it, so the state a step commits is consistent).
void CorrespondenceMaterial::completeForce(const FamilyView& fam, const double* y, StateStore& state,
                                           double* force) const {
  const bool stressDamage = fam.brokenN && fam.tensileStrength > 0.0;
  const std::size_t stride = static_cast<std::size_t>(fam.exchangeStride);
  double* hgField[3];
  hourglassFields(state, hgField);
  double hgScratch[3];
  double* hg = hgField[0] ? hgScratch : nullptr;
  for (int i = fam.begin; i < fam.end; ++i) {
    if (fam.exchange[stride * i + kRowFlag] == 0.0) continue;  // summed one-pass in computeForce (gathers)
    if (stressDamage) {
      const double s1i = fam.exchange[stride * i + kRowS1];
      double count = 0.0;
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
        const double s1j = fam.exchange[stride * fam.neighbors[b] + kRowS1];
        const bool broken = bondBrokenByStress(fam.brokenN[b], s1i, s1j, fam.tensileStrength);
        fam.broken[b] = broken ? 1.0 : 0.0;
        count += broken ? 1.0 : 0.0;
      }
      const int nb = fam.offsets[i + 1] - fam.offsets[i];
      fam.brokenCount[i] = count;
      fam.damage[i] = nb > 0 ? count / nb : 0.0;
    }
    const double* broken = stressDamage ? fam.broken : nullptr;
    if (fam.band && fam.band[i] != 0.0) {
      const double* row = fam.exchange + stride * i + kRowKinv;
      Mat3 Kinv;
      std::copy(row, row + 9, Kinv.begin());
      addBandForce(fam, i, y, Kinv, fam.exchange, fam.exchangeStride, force, broken, hg);
    } else
      addGatheredForce(fam, i, y, fam.exchange, fam.exchangeStride, force, broken, hg);
    if (hg)
      for (int a = 0; a < 3; ++a) hgField[a][i] = hg[a];
  }
}

void CorrespondenceMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  // |dP/dH| <= max(3K, 2mu) for the small-strain elastic map; with a_i = sum omega |K^-1 xi| V_j the point's
  // own stress contributes <= 2 C a_i^2 and its neighbours' stresses about as much (their a taken equal to
  // a_i: the view has no ghost families). The hourglass bonds act like bond-based springs c/|xi|.
  const double C = std::max(3.0 * moduli_.bulk, 2.0 * moduli_.shear);
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = hourglassConstant(horizonAt(fam, i));
    // A singular K is reported by the first force evaluation, which fails on every rank together (this
    // runs while the model is built, where a throw on one rank would leave the others in a collective).
    ShapeAndGradient sg;
    const bool regular = tryShapeAndGradient(fam, i, fam.x, isPlanar(dim_), sg);
    const Mat3 Kinv = regular ? sg.Kinv : Mat3{};
    double a = 0.0, h = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = (fam.unitInfluence ? 1.0 : fam.influence[b]) * fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      double kx[3] = {0, 0, 0};
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) kx[r] += Kinv[3 * r + s] * (fam.x[3 * j + s] - fam.x[3 * i + s]);
      a += w * std::sqrt(kx[0] * kx[0] + kx[1] * kx[1] + kx[2] * kx[2]);
      h += fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0) / fam.refLength[b];
    }
    bound[i] = 4.0 * C * a * a + 2.0 * c * h;
    // The band's traction term -P n / dx: P_i moves with u_i and its neighbours by at most C a per unit u.
    if (fam.outerNormal && fam.layerThickness[i] > 0.0) {
      const double* nv = fam.outerNormal + 3 * i;
      bound[i] += 2.0 * C * a * std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]) / fam.layerThickness[i];
    }
  }
}

void CorrespondenceMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  // The bond-based solid with the same bulk modulus, plus the hourglass spring: a preconditioner only
  // needs the scale of each bond's stiffness.
  for (int i = fam.begin; i < fam.end; ++i) {
    const double base = micromodulus(horizonAt(fam, i)) * (1.0 + hourglass_);
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) c[b] = base / fam.refLength[b];
  }
}

}  // namespace pf
