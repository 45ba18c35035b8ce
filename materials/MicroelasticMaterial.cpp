#include "MicroelasticMaterial.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/BondDamage.hpp"
#include "core/InputError.hpp"
#include "core/ElasticModuli.hpp"
#include "SolidParameters.hpp"

namespace pf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// 4 W1, W1 = continuum energy density per eps^2 of the isotropic stretch eps (every direction of the
// model's space) of the isotropic solid with bulk modulus K and the model's Poisson's ratio:
//   3D:           W = K (3 eps)^2 / 2              -> W1 = 9K/2
//   plane stress: W = E eps^2 / (1 - nu), nu = 1/3, E = 3K(1 - 2 nu) = K          -> W1 = 3K/2
//   plane strain: W = 2 (lambda + mu) eps^2, nu = 1/4, lambda = mu = 3K/5          -> W1 = 12K/5
double fourW1(Dimension dim, double K) {
  switch (dim) {
    case Dimension::ThreeD: return 18.0 * K;
    case Dimension::PlaneStress: return 6.0 * K;
    case Dimension::PlaneStrain: return 9.6 * K;
  }
  return 0.0;
}

// Q = integral of |xi| over the horizon (nodal volumes carry the thickness h in 2D): pi delta^4 in 3D,
// h 2 pi delta^3 / 3 in 2D. An isotropic stretch stores W = (c/4) eps^2 Q, so c = 4 W1 / Q: 3D
// c = 18K/(pi delta^4) (Silling & Askari 2005), plane stress c = 9K/(pi h delta^3) = 9E/(pi h delta^3)
// (Ha & Bobaru 2010), plane strain c = 72K/(5 pi h delta^3) = 48E/(5 pi h delta^3).
double continuumMoment(Dimension dim, double delta, double h) {
  if (dim == Dimension::ThreeD) return kPi * std::pow(delta, 4);
  return h * 2.0 * kPi * std::pow(delta, 3) / 3.0;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double bondFraction(const FamilyView& fam, int b) { return fam.fraction ? fam.fraction[b] : 1.0; }

}  // namespace

MicroelasticMaterial::MicroelasticMaterial(const MaterialInput& in)
    : MicroelasticMaterial(in, Calibration{"Thickness", false, true}) {}

MicroelasticMaterial::MicroelasticMaterial(const MaterialInput& in, const Calibration& cal)
    : dim_(dimensionFrom(in, &thickness_, cal.thicknessName)), density_(in.get("Density")), influence_(cal.influence) {
  const std::string where = in.inputFile + ": material '" + in.name + "'";
  const bool K = in.has("Bulk Modulus"), E = in.has("Young's Modulus");
  if (K == E)
    throw InputError(where + " needs exactly one of 'Bulk Modulus', 'Young's Modulus' (a bond-based solid has "
                             "one elastic constant)");
  const double nu = poissonRatio();
  bulk_ = K ? in.get("Bulk Modulus") : in.get("Young's Modulus") / (3.0 * (1.0 - 2.0 * nu));
  // Peridigm's Elastic Bond Based (elastic_bond_based.cxx) takes c = 12K/(pi h delta^3) in plane stress and
  // plane strain alike: with Q = h 2 pi delta^3 / 3, 4 W1 = 8K, i.e. W = 2K eps^2, the energy of a 2D solid whose
  // in-plane bulk modulus is the K given (not the plane-stress 3K/4 or plane-strain 6K/5 of nu's 3D solid).
  fourW1_ = cal.peridigmPlanar && dim_ != Dimension::ThreeD ? 8.0 * bulk_ : fourW1(dim_, bulk_);
  // A bond-based solid's Poisson's ratio is fixed; a deck may state it, but only as that value (to 1e-3,
  // so that 0.333 passes for 1/3).
  if (in.has("Poisson's Ratio") && std::fabs(in.get("Poisson's Ratio") - nu) > 1e-3)
    throw InputError(where + ": 'Poisson's Ratio' = " + number(in.get("Poisson's Ratio")) +
                     ", but a bond-based solid has nu = " + (nu == 0.25 ? "1/4" : "1/3") + " in " + toString(dim_) +
                     " (omit it or give that value)");
  // The free stretch of a bond, alpha dT; in plane strain (1 + nu) alpha dT, as "Elastic" (the held
  // out-of-plane direction adds nu alpha dT to the free in-plane strain).
  const double alpha = in.get("Thermal Expansion Coefficient", 0.0);
  thermal_ = dim_ == Dimension::PlaneStrain ? (1.0 + nu) * alpha : alpha;
}

std::vector<std::string> MicroelasticMaterial::fieldsRead() const {
  if (thermal_ == 0.0) return {};
  return {"Temperature_Change"};
}

MaterialEntry MicroelasticMaterial::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params = {
      P::real("Density", "mass density [kg/m^3]").need().positive(),
      P::real("Bulk Modulus", "K [Pa]; give this or Young's Modulus").positive(),
      P::real("Young's Modulus", "E [Pa] = 3K(1 - 2 nu)").positive(),
      P::real("Poisson's Ratio", "optional; must be the model's: 1/4 (3D, plane strain), 1/3 (plane stress)")
          .above(-1.0).below(0.5),
      P::flag("Plane Stress", "2D plane-stress model (nu = 1/3; needs Thickness)").byDefault("false"),
      P::flag("Plane Strain", "2D plane-strain model (nu = 1/4; needs Thickness)").byDefault("false"),
      P::real("Thickness", "out-of-plane thickness of a 2D model [m]").positive(),
  };
  MaterialEntry e{"Microelastic",
                  "bond-based prototype microelastic solid (PMB, Silling & Askari 2005; breaks with a Damage Model)",
                  withThermalExpansion(params),
                  [](const MaterialInput& in) { return std::unique_ptr<Material>(new MicroelasticMaterial(in)); },
                  {"Stored_Elastic_Energy"}};
  e.createOperators = [](const MaterialInput& in) {
    double thickness = 0.0;
    const Dimension dim = dimensionFrom(in, &thickness);
    return heatTermsOf(in, dim, thickness);
  };
  return e;
}

std::vector<StateSpec> MicroelasticMaterial::stateSpecs() const {
  return {{"Stored_Elastic_Energy", Location::Node, false, true}};
}

void MicroelasticMaterial::enableOutput(const std::string& name) const {
  if (name == "Stored_Elastic_Energy") energyWanted_ = true;
}

double MicroelasticMaterial::micromodulus(const FamilyView& fam, int i) const {
  const double c = fourW1_ / continuumMoment(dim_, fam.horizon, thickness_);
  if (fam.unitInfluence || !influence_) return c;
  // The continuum c is calibrated for omega = 1. With an influence function the pair force is omega c s,
  // so c is divided by the family's mean omega (weighted by |xi| V_j, as Q weights the bonds): the bulk
  // modulus stays K. For omega = 1 both sums are the same bits and the ratio is exactly 1.
  double weighted = 0.0, plain = 0.0;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const double xv = fam.refLength[b] * fam.volume[fam.neighbors[b]] * bondFraction(fam, b);
    weighted += omega(fam, b) * xv;
    plain += xv;
  }
  return weighted > 0.0 ? c * plain / weighted : c;
}

void MicroelasticMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state,
                                        double* force) const {
  if (thermal_ != 0.0) forces<true>(fam, y, state, force);
  else forces<false>(fam, y, state, force);
}

template <bool Thermal>
void MicroelasticMaterial::forces(const FamilyView& fam, const double* y, StateStore& state, double* force) const {
  double* energy = energyWanted_ ? state.trial("Stored_Elastic_Energy") : nullptr;
  const double* dT = Thermal ? fam.fields->find("Temperature_Change") : nullptr;
  for (int i = fam.begin; i < fam.end; ++i) {
    // T = c omega s / 2 along M is node i's half of the pair force: node j's own loop adds the other half
    // (f_i += T V_j, f_j -= T V_i, both ends, as the state-based models). With c_i = c_j this is PMB's
    // f = c omega s M; the stored energy V_i (c_i/4) sum omega s^2 |xi| V_j is the potential of these forces.
    // Thermal: node i's half loses node i's free stretch a dT_i (so the pair force sees the mean of its ends'),
    // in the force, the energy and the critical-stretch test.
    const double c = micromodulus(fam, i), Vi = fam.volume[i];
    const double strain = Thermal ? thermal_ * dT[i] : 0.0;
    const double* yi = y + 3 * i;
    double fi[3] = {0.0, 0.0, 0.0}, w = 0.0, broken = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double d[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), xi = fam.refLength[b];
      const double mech = Thermal ? len - strain * xi : len;  // the length less the free thermal extension
      if (fam.brokenN && breakBond(fam, b, mech)) {  // a broken bond carries no force and stores no energy
        broken += 1.0;
        continue;
      }
      const double om = omega(fam, b), fr = bondFraction(fam, b);
      const double s = (mech - xi) / xi, g = 0.5 * c * om * s / len;
      const double vj = fam.volume[j] * fr, vi = Vi * fr;
      for (int a = 0; a < 3; ++a) {
        fi[a] += g * d[a] * vj;
        force[3 * j + a] -= g * d[a] * vi;
      }
      w += om * s * s * xi * vj;
    }
    for (int a = 0; a < 3; ++a) force[3 * i + a] += fi[a];
    if (energy) energy[i] = 0.25 * c * w * Vi;
    const int n = fam.offsets[i + 1] - fam.offsets[i];
    if (fam.brokenN) finishNode(fam, i, n, broken);  // every flag was written: always a valid trial
  }
}

bool MicroelasticMaterial::forceDerivative(const FamilyView& fam, const double* y, const double* dy,
                                           const StateStore&, double* dforce) const {
  if (thermal_ != 0.0) derivative<true>(fam, y, dy, dforce);
  else derivative<false>(fam, y, dy, dforce);
  return true;
}

template <bool Thermal>
void MicroelasticMaterial::derivative(const FamilyView& fam, const double* y, const double* dy, double* dforce) const {
  // d(T M) = dT M + T (I - M M^T) dY / |Y|, dT = c omega (M . dY) / (2 |xi|): exact, rotations included. The
  // temperature is held (a given field), so the thermal stretch changes T only.
  const double* dT = Thermal ? fam.fields->find("Temperature_Change") : nullptr;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = micromodulus(fam, i), Vi = fam.volume[i];
    const double strain = Thermal ? thermal_ * dT[i] : 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      if (fam.brokenN && fam.broken[b] != 0.0) continue;  // as the force evaluation at y left it
      const int j = fam.neighbors[b];
      double d[3], dd[3];
      for (int a = 0; a < 3; ++a) {
        d[a] = y[3 * j + a] - y[3 * i + a];
        dd[a] = dy[3 * j + a] - dy[3 * i + a];
      }
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), xi = fam.refLength[b];
      const double M[3] = {d[0] / len, d[1] / len, d[2] / len};
      const double de = M[0] * dd[0] + M[1] * dd[1] + M[2] * dd[2];
      const double half = 0.5 * c * omega(fam, b) / xi, fr = bondFraction(fam, b);
      const double T = half * ((Thermal ? len - strain * xi : len) - xi), dTde = half * de;
      for (int a = 0; a < 3; ++a) {
        const double dTM = dTde * M[a] + T * (dd[a] - M[a] * de) / len;
        dforce[3 * i + a] += dTM * fam.volume[j] * fr;
        dforce[3 * j + a] -= dTM * Vi * fr;
      }
    }
  }
}

void MicroelasticMaterial::pairStiffness(const FamilyView& fam, double* stiffness) const {
  // dT/de of node i's half of the bond: c omega / (2 |xi|) (partial volumes: times the bond's share).
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = micromodulus(fam, i);
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      stiffness[b] = 0.5 * c * omega(fam, b) * bondFraction(fam, b) / fam.refLength[b];
  }
}

void MicroelasticMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  // dF_i/du_j = k_ij n n^T with k_ij = (c_i + c_j) omega V_j / (2 |xi|) (both halves of the bond; the
  // geometric term T/|Y| (I - M M^T) is smaller by the stretch, below 1e-2 in the elastic range and
  // dropped). c_j is taken as c_i: the same model, and the same family mean of omega up to the surface
  // layer. Row sum over the bond's off-diagonal block and its share of the diagonal: 2 k |n_a| |n|_1.
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = micromodulus(fam, i);
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double x = fam.refLength[b];
      double n1 = 0.0, nmax = 0.0;
      for (int d = 0; d < 3; ++d) {
        const double n = std::fabs(fam.x[3 * j + d] - fam.x[3 * i + d]) / x;
        n1 += n;
        nmax = std::max(nmax, n);
      }
      sum += c * omega(fam, b) * bondFraction(fam, b) * fam.volume[j] / x * nmax * n1;
    }
    bound[i] = 2.0 * sum;
  }
}

}  // namespace pf
