#include "PalsMaterial.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/BondDamage.hpp"
#include "core/InputError.hpp"
#include "PalsInfluence.hpp"
#include "SolidParameters.hpp"

namespace pf {

namespace {

using pals::kModes;
const char* const kNormDil = "Dilatation_Normalization";
const char* const kNormDev = "Deviatoric_Normalization";
const char* const kOmega = "Pals_Omega";
const char* const kSigma = "Pals_Sigma";

std::string multiplierName(bool dilatation, int k) {
  return std::string(dilatation ? "Lagrange_Multiplier_Dilatation_" : "Lagrange_Multiplier_Deviatoric_") +
         std::to_string(k + 1);
}

// One bond of node i in the reference configuration: z = x_j - x_i and |z|, as Peridigm forms them.
struct RefBond {
  double z[3];
  double xi;
};
RefBond refBond(const FamilyView& fam, int i, int j) {
  RefBond r;
  for (int c = 0; c < 3; ++c) r.z[c] = fam.x[3 * j + c] - fam.x[3 * i + c];
  r.xi = std::sqrt(r.z[0] * r.z[0] + r.z[1] * r.z[1] + r.z[2] * r.z[2]);
  return r;
}

double neighbourVolume(const FamilyView& fam, int b) {
  return fam.volume[fam.neighbors[b]] * (fam.fraction ? fam.fraction[b] : 1.0);
}

// The multipliers of owned node i from its whole reference family (Peridigm: computed once, at initialisation).
pals::Multipliers multipliersOf(const FamilyView& fam, int i, const Influence& w0, const Influence& s0) {
  pals::MultiplierSystem sys;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const RefBond r = refBond(fam, i, fam.neighbors[b]);
    sys.add(r.z, neighbourVolume(fam, b), influenceValue(w0, r.xi, fam.horizon), influenceValue(s0, r.xi, fam.horizon));
  }
  pals::Multipliers m;
  if (!sys.solve(m)) {
    const double* x = fam.x + 3 * i;
    throw InputError("material 'Pals': the family of the point at (" + std::to_string(x[0]) + ", " +
                     std::to_string(x[1]) + ", " + std::to_string(x[2]) + ") (" +
                     std::to_string(fam.offsets[i + 1] - fam.offsets[i]) +
                     " bonds) does not determine its influence functions (a singular moment system); "
                     "a larger Horizon gives it more bonds");
  }
  return m;
}

// The per-bond influence values of node i: omega and sigma of each bond, from its multipliers.
void influencesOf(const FamilyView& fam, int i, const pals::Multipliers& m, const Influence& w0,
                  const Influence& s0, double* om, double* sg) {
  for (int b = fam.offsets[i], k = 0; b < fam.offsets[i + 1]; ++b, ++k) {
    const RefBond r = refBond(fam, i, fam.neighbors[b]);
    om[k] = pals::omega(r.z, influenceValue(w0, r.xi, fam.horizon), m.dilatation);
    sg[k] = pals::sigma(r.z, influenceValue(s0, r.xi, fam.horizon), m.deviatoric);
  }
}

}  // namespace

PalsMaterial::PalsMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")),
      omega0_(influenceFromName(in.text("Dilatation Influence Function"), in.where())),
      sigma0_(influenceFromName(in.text("Deviatoric Influence Function"), in.where())) {}

MaterialEntry PalsMaterial::entry() {
  using P = ParameterSpec;
  std::vector<ParameterSpec> params;
  for (ParameterSpec& p : elasticSolidParameters())
    if (p.name != "Plane Stress" && p.name != "Plane Strain" && p.name != "Thickness" &&
        p.name != "Apply Shear Correction Factor")
      params.push_back(std::move(p));
  const std::vector<std::string> kinds = {"One", "Parabolic Decay", "Gaussian"};
  params.push_back(P::text("Dilatation Influence Function", "omega0(|xi|, delta) of the dilatation (Peridigm's "
                                                             "predefined functions)").oneOf(kinds).byDefault("One"));
  params.push_back(P::text("Deviatoric Influence Function", "sigma0(|xi|, delta) of the deviatoric part")
                       .oneOf(kinds)
                       .byDefault("One"));
  params.push_back(P::real("Hourglass Coefficient", "accepted, ignored: Peridigm's Pals model does not read it")
                       .nonNegative());
  std::vector<std::string> outputs = {"Dilatation", "Stored_Elastic_Energy_Density", kNormDil, kNormDev};
  for (int dil = 1; dil >= 0; --dil)
    for (int k = 0; k < kModes; ++k) outputs.push_back(multiplierName(dil == 1, k));
  return MaterialEntry{"Pals",
                       "Peridigm's position-aware linear solid (Mitchell, Silling & Littlewood 2015), 3D", params,
                       [](const MaterialInput& in) { return std::unique_ptr<Material>(new PalsMaterial(in)); },
                       outputs};
}

std::vector<StateSpec> PalsMaterial::stateSpecs() const {
  std::vector<StateSpec> s = {{"Dilatation", Location::Node, false, true},
                              {"Stored_Elastic_Energy_Density", Location::Node, false, true},
                              {kNormDil, Location::Node, false, true},
                              {kNormDev, Location::Node, false, true}};
  for (int dil = 1; dil >= 0; --dil)
    for (int k = 0; k < kModes; ++k) s.push_back({multiplierName(dil == 1, k), Location::Node, false, true});
  // omega and sigma of each bond, kept from the node's first evaluation (the derivative reads them per product)
  s.push_back({kOmega, Location::Bond, false, false});
  s.push_back({kSigma, Location::Bond, false, false});
  return s;
}

void PalsMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const {
  const double K = moduli_.bulk, MU = moduli_.shear, TWO_MU = 2.0 * MU;
  double* lam[kModes];
  double* tau[kModes];
  for (int k = 0; k < kModes; ++k) lam[k] = state.trial(multiplierName(true, k)), tau[k] = state.trial(multiplierName(false, k));
  double* normDil = state.trial(kNormDil);
  double* normDev = state.trial(kNormDev);
  double* theta = state.trial("Dilatation");
  double* energy = state.trial("Stored_Elastic_Energy_Density");
  double* omega = state.trial(kOmega);
  double* sigma = state.trial(kSigma);
  std::vector<double> e, len, intact;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
    // The multipliers and influences depend on the reference family only: set at a node's first evaluation (after
    // a restart again; Peridigm's normalising constants are 1, as here).
    if (normDev[i] == 0.0) {
      const pals::Multipliers mult = multipliersOf(fam, i, omega0_, sigma0_);
      for (int k = 0; k < kModes; ++k) lam[k][i] = mult.dilatation[k], tau[k][i] = mult.deviatoric[k];
      influencesOf(fam, i, mult, omega0_, sigma0_, omega + b0, sigma + b0);
      normDil[i] = normDev[i] = 1.0;
    }
    const double* om = omega + b0;
    const double* sg = sigma + b0;
    e.resize(n), len.resize(n), intact.resize(n);
    const double* Y = y + 3 * i;
    double th = 0.0, p = 0.0, m = 0.0, broken = 0.0;
    for (int k = 0; k < n; ++k) {
      const int b = b0 + k, j = fam.neighbors[b];
      const RefBond r = refBond(fam, i, j);
      const double* YP = y + 3 * j;
      const double dx = YP[0] - Y[0], dy = YP[1] - Y[1], dz = YP[2] - Y[2];
      len[k] = std::sqrt(dx * dx + dy * dy + dz * dz);
      e[k] = len[k] - r.xi;
      intact[k] = 1.0;
      const double V = neighbourVolume(fam, b);
      const double xi2 = r.z[0] * r.z[0] + r.z[1] * r.z[1] + r.z[2] * r.z[2];
      m += sg[k] * xi2 * V;  // the weighted volume keeps its reference value (as Peridigm's m, docs/input.md)
      if (fam.brokenN && breakBond(fam, b, len[k])) {  // a broken bond leaves every other sum
        intact[k] = 0.0;
        broken += 1.0;
        continue;
      }
      const double omega_x = om[k] * r.xi, sigma_x = sg[k] * r.xi;
      th += omega_x * e[k] * V;
      p += -(TWO_MU * sigma_x / 3.0) * e[k] * V;
    }
    if (fam.brokenN) finishNode(fam, i, n, broken);
    p += (K + TWO_MU * m / 9.0) * th;
    theta[i] = th;
    double sum = 0.0;
    const double Vi = fam.volume[i];
    for (int k = 0; k < n; ++k) {
      if (intact[k] == 0.0) continue;
      const int b = b0 + k, j = fam.neighbors[b];
      const double xi = refBond(fam, i, j).xi;
      const double eps = e[k] - th * xi / 3.0;
      const double t = p * om[k] * xi + TWO_MU * sg[k] * eps;
      const double* YP = y + 3 * j;
      const double frac = fam.fraction ? fam.fraction[b] : 1.0;
      const double Vj = fam.volume[j] * frac;
      for (int c = 0; c < 3; ++c) {
        const double f = t * (YP[c] - Y[c]) / len[k];
        force[3 * i + c] += f * Vj;
        force[3 * j + c] -= f * (Vi * frac);
      }
      const double epsW = e[k] - xi * th / 3.0;  // Peridigm's energy pass forms it in this order
      sum += sg[k] * epsW * epsW * Vj;
    }
    energy[i] = 0.5 * K * th * th + MU * sum;
  }
}

// d(t n) along dy, per bond: de = n . (dy_j - dy_i), dtheta = sum omega |z| de V, dp = (K + 2 mu m/9) dtheta - (2 mu/3)
// sum sigma |z| de V, dt = dp omega |z| + 2 mu sigma (de - dtheta |z|/3), d(t n) = dt n + t (dY - n (n . dY)) / |Y|.
// The multipliers are read from the state computeForce filled; a bond whose trial flag is set is absent.
bool PalsMaterial::forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                                   double* dforce) const {
  const double K = moduli_.bulk, TWO_MU = 2.0 * moduli_.shear;
  const double* normDev = state.trial(kNormDev);
  std::vector<double> omLocal, sgLocal, len, de, n3;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
    const double* om = state.trial(kOmega) + b0;
    const double* sg = state.trial(kSigma) + b0;
    if (normDev[i] == 0.0) {  // not evaluated yet: from the reference family now
      omLocal.resize(n), sgLocal.resize(n);
      influencesOf(fam, i, multipliersOf(fam, i, omega0_, sigma0_), omega0_, sigma0_, omLocal.data(), sgLocal.data());
      om = omLocal.data(), sg = sgLocal.data();
    }
    len.resize(n), de.resize(n), n3.resize(3 * n);
    const double* Y = y + 3 * i;
    double th = 0.0, p = 0.0, m = 0.0, dth = 0.0, dpb = 0.0;
    for (int k = 0; k < n; ++k) {
      const int b = b0 + k, j = fam.neighbors[b];
      const double xi = fam.refLength[b], V = neighbourVolume(fam, b);
      m += sg[k] * xi * xi * V;
      if (fam.broken && fam.broken[b] != 0.0) continue;
      double d[3], dd[3];
      for (int c = 0; c < 3; ++c) d[c] = y[3 * j + c] - Y[c], dd[c] = dy[3 * j + c] - dy[3 * i + c];
      len[k] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int c = 0; c < 3; ++c) n3[3 * k + c] = d[c] / len[k];
      de[k] = n3[3 * k] * dd[0] + n3[3 * k + 1] * dd[1] + n3[3 * k + 2] * dd[2];
      const double e = len[k] - xi;
      th += om[k] * xi * e * V;
      p -= TWO_MU * sg[k] * xi / 3.0 * e * V;
      dth += om[k] * xi * de[k] * V;
      dpb -= TWO_MU * sg[k] * xi / 3.0 * de[k] * V;
    }
    p += (K + TWO_MU * m / 9.0) * th;
    const double dp = dpb + (K + TWO_MU * m / 9.0) * dth;
    const double Vi = fam.volume[i];
    for (int k = 0; k < n; ++k) {
      const int b = b0 + k, j = fam.neighbors[b];
      if (fam.broken && fam.broken[b] != 0.0) continue;
      const double xi = fam.refLength[b], e = len[k] - xi;
      const double t = p * om[k] * xi + TWO_MU * sg[k] * (e - th * xi / 3.0);
      const double dt = dp * om[k] * xi + TWO_MU * sg[k] * (de[k] - dth * xi / 3.0);
      const double frac = fam.fraction ? fam.fraction[b] : 1.0;
      const double Vj = fam.volume[j] * frac;
      for (int c = 0; c < 3; ++c) {
        const double ddc = dy[3 * j + c] - dy[3 * i + c];
        const double df = dt * n3[3 * k + c] + t * (ddc - n3[3 * k + c] * de[k]) / len[k];
        dforce[3 * i + c] += df * Vj;
        dforce[3 * j + c] -= df * (Vi * frac);
      }
    }
  }
  return true;
}

// Each bond's force depends on its own extension (2 mu sigma) and, through theta and p, on every extension of the
// family: |dt_b/de_k| <= |omega_b| |z_b| |dp/de_k| + (2 mu / 3) |sigma_b| |z_b| |omega_k| |z_k| V_k. Summed over the
// bonds with V_j, twice (u_j and u_i both move the extension), plus the turning stiffness is neglected (small
// strain: |t| / |Y| is of the order of the extension stiffness times the strain).
void PalsMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  const double K = moduli_.bulk, TWO_MU = 2.0 * moduli_.shear;
  std::vector<double> om, sg;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
    om.resize(n), sg.resize(n);
    influencesOf(fam, i, multipliersOf(fam, i, omega0_, sigma0_), omega0_, sigma0_, om.data(), sg.data());
    double m = 0.0, sumW = 0.0, sumS = 0.0;
    for (int k = 0; k < n; ++k) {
      const double xi = fam.refLength[b0 + k], V = neighbourVolume(fam, b0 + k);
      m += sg[k] * xi * xi * V;
      sumW += std::fabs(om[k]) * xi * V;
      sumS += std::fabs(sg[k]) * xi * V;
    }
    const double dp = std::fabs(K + TWO_MU * m / 9.0) * sumW + TWO_MU * sumS / 3.0;  // sum_k |dp/de_k|
    double s = 0.0;
    for (int k = 0; k < n; ++k) {
      const double xi = fam.refLength[b0 + k], V = neighbourVolume(fam, b0 + k);
      s += V * (TWO_MU * std::fabs(sg[k]) + std::fabs(om[k]) * xi * dp + TWO_MU * std::fabs(sg[k]) * xi * sumW / 3.0);
    }
    bound[i] = 2.0 * s;
  }
}

// The bond's own extension stiffness: 2 mu sigma from the deviatoric part and K omega^2 |z|^2 V_j from its own share of
// theta (the coupling to the other bonds is left to the Krylov operator).
void PalsMaterial::pairStiffness(const FamilyView& fam, double* c) const {
  std::vector<double> om, sg;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
    om.resize(n), sg.resize(n);
    influencesOf(fam, i, multipliersOf(fam, i, omega0_, sigma0_), omega0_, sigma0_, om.data(), sg.data());
    for (int k = 0; k < n; ++k) {
      const double xi = fam.refLength[b0 + k];
      c[b0 + k] = 2.0 * moduli_.shear * std::fabs(sg[k]) + moduli_.bulk * om[k] * om[k] * xi * xi * neighbourVolume(fam, b0 + k);
    }
  }
}

}  // namespace pf
