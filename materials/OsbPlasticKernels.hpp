#pragma once
// Bond loop of the OSB J2 solid with linear isotropic (K) and kinematic (H) hardening (Pirzadeh et al. 2024
// §3.2; Mitchell 2011 when K = H = 0) in 3D, plane stress and plane strain: gathers each family, calls the
// per-node return mapping (J2ReturnMapping.hpp) and scatters the force; no allocation. Derivation and the
// deviations from the paper (2D constants, plane-strain dilatation, plane-stress flow): docs/materials.md.
#include "core/BondFamily.hpp"
#include "core/Dimension.hpp"
#include "OsbConstants.hpp"

namespace pf {

// Which weighted volume the yield-surface constants (Eqs. 36, 39, 46) are written with.
enum class YieldNormalization {
  Discrete,    // the node's own m (lattice-consistent: the 3D return is then exactly radial, 3 mu)
  Continuum,   // 4 pi delta^5 / 5 (3D), pi h delta^4 / 2 (2D): the paper's constants
};

struct J2Parameters {
  OsbConstants osb;
  Dimension dim = Dimension::ThreeD;
  double thickness = 0.0;          // 2D only (continuum normalisation)
  double yieldStress = 0.0;        // sigma_y0
  double isoHardening = 0.0;       // K
  double kinHardening = 0.0;       // H
  YieldNormalization norm = YieldNormalization::Continuum;
  // Peridigm's "Hardening Modulus" H and its law (PeridigmHardening.hpp) instead of K and H above.
  bool peridigmLaw = false;
  double peridigmHardening = 0.0;
  // `Gradient Correction` = `Quadratic`: each point reads its bonds with the quadratic part of the deformation removed
  // (OsbGradientCorrection.hpp); the force and its tangent alike.
  bool gradientCorrection = false;
  int maxIterations = 10;
  double tolerance = 1e-12;        // relative residual of Eq. 50 (written as sigma_vm - sigma_bar)
};

// Committed (n, read) and trial (n+1, written) arrays. Node arrays are indexed by node, bond arrays by
// bond. iterations may be null; vm/svm/theta are outputs.
struct J2Fields {
  const double* edpN; double* edp;            // Deviatoric_Plastic_Extension
  const double* lambdaN; double* lambda;      // Lambda (accumulated)
  const double* alphaN; double* alpha;        // Equivalent_Plastic_Strain
  const double* qN; double* q;                // Back_Stress (scalar)
  const double* signN; double* sign;          // Von_Mises_Sign: +1/-1, 0 = never set (taken as +1)
  double* vonMises; double* signedVonMises; double* theta;
  double* iterations;                         // Newton iterations of the last update (0 if elastic)
  // Dissipated_Energy [J per node]: the plastic work sigma_vm |d eps_p| V_i accumulated (null: not kept)
  const double* dissipatedN = nullptr; double* dissipated = nullptr;
  // Per node: Peridigm's shear correction factor s (ShearCorrectionFactor.hpp), or null for s = 1. It
  // scales the deviatoric modulus (15 mu s / m) and the yield value (s^2 psi0), as Peridigm's
  // elastic_plastic_hardening.cxx does.
  const double* scf = nullptr;
};

// Updates the plastic state of owned nodes [fam.begin, fam.end) from the committed state and adds the
// force densities (f_i += T V_j, f_j -= T V_i) as ElasticMaterial does. Throws ConstitutiveFailure if
// Newton does not reach the tolerance within maxIterations.
void osbJ2Force(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s,
                double* force);

// Thermal expansion of the J2 solid, per unit Temperature_Change dT_i of the node owning the bond (Peridigm's rule
// for its elastic model, materials/OsbThermalKernels.hpp; docs/thermal.md):
//   3D, plane stress: every bond of node i loses its free thermal extension alpha dT_i |xi| before anything else
//     (dilatation, deviatoric split, return mapping, critical stretch): extension = breaking = alpha, volume = 0.
//   plane strain: the thermal strain alpha dT I, its held out-of-plane part included, is hydrostatic, so the
//     deviatoric state and the flow see the total in-plane extension and only the dilatation loses
//     theta_th = volume dT_i sum omega |xi|^2 V_j / m (volume = 3 alpha: 3 alpha dT for a whole family);
//     extension = 0, breaking = (1 + nu) alpha (the free in-plane stretch, as "Elastic" breaks bonds).
struct J2Thermal {
  double extension = 0.0, breaking = 0.0, volume = 0.0;
};

// osbJ2Force with thermal expansion; dT: Temperature_Change per overlap node. The Dilatation written is the
// mechanical one. osbJ2Force's node update over a thermal gather (OsbThermalPlasticKernels.cpp): the
// mechanics-only kernel is untouched.
void osbJ2ThermalForce(const FamilyView& fam, const J2Parameters& p, const J2Thermal& th, const double* dT,
                       const double* y, const J2Fields& s, double* force);

}  // namespace pf
