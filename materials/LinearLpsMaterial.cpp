#include "LinearLpsMaterial.hpp"

#include "core/InputError.hpp"
#include "OsbKernels.hpp"
#include "SolidParameters.hpp"

namespace pf {

namespace {

// Adds the linear force of the displacement field u (3 per overlap node) for owned [begin, end) and writes each
// node's dilatation to theta (may be null). Peridigm's two loops (precompute, computeForce) in one pass per node:
// f_ij needs theta_i only.
void linearLpsForce(const FamilyView& fam, const ElasticModuli& em, const double* u, double* theta, double* force) {
  const double K = em.bulk, G = em.shear;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], b1 = fam.offsets[i + 1];
    const double* xi = fam.x + 3 * i;
    const double* ui = u + 3 * i;
    double th = 0.0;
    for (int b = b0; b < b1; ++b) {
      const int j = fam.neighbors[b];
      const double z[3] = {fam.x[3 * j] - xi[0], fam.x[3 * j + 1] - xi[1], fam.x[3 * j + 2] - xi[2]};
      const double zu = z[0] * (u[3 * j] - ui[0]) + z[1] * (u[3 * j + 1] - ui[1]) + z[2] * (u[3 * j + 2] - ui[2]);
      const double Vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      th += fam.influence[b] * zu * Vj;
    }
    const double m = fam.weightedVolume[i];
    // A point without bonds (m = 0) has no dilatation: 0, as Peridigm writes.
    th = b1 > b0 ? 3.0 * th / m : 0.0;
    if (theta) theta[i] = th;
    const double iso = (9.0 * K - 15.0 * G) * th / (3.0 * m);
    for (int b = b0; b < b1; ++b) {
      const int j = fam.neighbors[b];
      const double z[3] = {fam.x[3 * j] - xi[0], fam.x[3 * j + 1] - xi[1], fam.x[3 * j + 2] - xi[2]};
      const double zz = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
      const double zu = z[0] * (u[3 * j] - ui[0]) + z[1] * (u[3 * j + 1] - ui[1]) + z[2] * (u[3 * j + 2] - ui[2]);
      const double w = fam.influence[b];
      const double s = w * iso + 15.0 * G * w * zu / (m * zz);  // f_ij = s xi
      const double frac = fam.fraction ? fam.fraction[b] : 1.0;
      const double Vj = fam.volume[j] * frac, Vi = fam.volume[i] * frac;
      for (int c = 0; c < 3; ++c) {
        force[3 * i + c] += s * z[c] * Vj;
        force[3 * j + c] -= s * z[c] * Vi;
      }
    }
  }
}

}  // namespace

LinearLpsMaterial::LinearLpsMaterial(const MaterialInput& in)
    : moduli_(elasticModuliFrom(in)), density_(in.get("Density")),
      osb_(osbConstants(Dimension::ThreeD, moduli_)) {
  if (in.has("Use Partial Volume") && in.flag("Use Partial Volume"))
    throw InputError(in.inputFile + ": material '" + in.name + "': 'Use Partial Volume' = true needs Peridigm's "
                     "element-horizon intersections, which Periforge does not compute; use the discretization's "
                     "'Partial Volume' (regular grids) instead");
}

MaterialEntry LinearLpsMaterial::entry() {
  // The OSB solid's parameters without the planar ones (Peridigm's model is 3D) and the shear correction.
  std::vector<ParameterSpec> params;
  for (ParameterSpec& p : elasticSolidParameters())
    if (p.name != "Plane Stress" && p.name != "Plane Strain" && p.name != "Thickness" &&
        p.name != "Apply Shear Correction Factor")
      params.push_back(std::move(p));
  params.push_back(ParameterSpec::flag("Use Partial Volume",
                                       "Peridigm's element-horizon partial volumes: only false is supported")
                       .byDefault("false"));
  return MaterialEntry{"Linear LPS Partial Volume",
                       "Peridigm's linearised linear peridynamic solid (small displacements, 3D)", params,
                       [](const MaterialInput& in) { return std::unique_ptr<Material>(new LinearLpsMaterial(in)); },
                       {"Dilatation"}};
}

std::vector<StateSpec> LinearLpsMaterial::stateSpecs() const { return {{"Dilatation", Location::Node, false, true}}; }

void LinearLpsMaterial::computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const {
  std::vector<double> u(3 * static_cast<std::size_t>(fam.numNodes));
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = y[k] - fam.x[k];
  linearLpsForce(fam, moduli_, u.data(), state.trial("Dilatation"), force);
}

bool LinearLpsMaterial::forceDerivative(const FamilyView& fam, const double*, const double* dy, const StateStore&,
                                        double* dforce) const {
  linearLpsForce(fam, moduli_, dy, nullptr, dforce);
  return true;
}

void LinearLpsMaterial::stiffnessBound(const FamilyView& fam, double* bound) const {
  osbStiffnessBound(fam, osb_, bound);
}

void LinearLpsMaterial::pairStiffness(const FamilyView& fam, double* c) const { osbPairStiffness(fam, osb_, c); }

}  // namespace pf
