#pragma once
// The J2 stress updates of Peridigm's "Elastic Plastic Correspondence", "Isotropic Hardening Correspondence" and
// "Viscoplastic Needleman Correspondence" (src/materials/elastic_plastic_correspondence.cxx,
// isotropic_hardening_correspondence.cxx, viscoplastic_needleman_correspondence.cxx), on the unrotated
// Cauchy stress tau and the unrotated strain increment de = d dt of the correspondence kinematics. Both take the
// elastic trial tau_tr = tau_n + K tr(de) I + 2G dev(de) and, when plastic, scale its deviator s_tr onto the yield
// surface sqrt(3/2)|s| = Y (a radial return). The equivalent plastic strain follows Peridigm's "generic" increment:
//   d eps_p = max(0, sqrt(2/3) (dev(de) - (s - s_n)/(2G)) : (s/|s_tr| + s_n/|s_n|)/2),
// the plastic part of the deviatoric strain increment projected on the mean of the two stress directions (s the
// returned deviator; |s_tr|, |s_n| at least 1e-20). For a radial return from a state on the surface along a fixed
// direction this is the classical (sigma_tr - Y)/(3G + H).
#include "core/Tensor3.hpp"

namespace pf {

struct PeridigmJ2Step {
  Mat3 tau;     // tau_n+1
  double eqps;  // equivalent plastic strain at n+1
};

// Perfect plasticity (elastic_plastic_correspondence.cxx): plastic when sigma_vm,tr > Y.
PeridigmJ2Step peridigmPerfectPlastic(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G, double Y);

// Linear isotropic hardening Y + H eps_p (isotropic_hardening_correspondence.cxx), with Peridigm's steps: elastic
// when sigma_vm,tr < Y (the initial yield stress); otherwise the multiplier
//   dl = (6G (s_tr : dev(de))/|s_tr| + 3|s_n| - sqrt(6) Y) / (2(H + 3G))
// gives the surface Y + H (eps_p,n + sqrt(2/3) dl), and the step is plastic when sigma_vm,tr exceeds it (then the
// return to that surface and the generic increment above).
PeridigmJ2Step peridigmIsotropicHardening(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G,
                                          double Y, double H);

// Needleman's rate-dependent flow stress, as Peridigm's model writes it (viscoplastic_needleman_correspondence.cxx,
// ViscoplasticNeedlemanYieldFunction): g(dl, eps) = Y (1 + eps/e0)^n / (1 + (eps/e1)^2) (sqrt(2/3) dl / (dt r0))^m.
struct NeedlemanLaw {
  double n = 0.0;      // Strain Hardening Exponent
  double m = 0.0;      // Rate Hardening Exponent
  double rate0 = 1.0;  // Reference Strain Rate r0 [1/s]
  double e0 = 1.0;     // Reference Strain 0
  double e1 = 1.0;     // Reference Strain 1
  double flowStress(double Y, double dl, double eps, double dt) const;
};

// Peridigm's Needleman update, step by step: elastic when sigma_vm,tr < Y; otherwise the multiplier dl of
//   (s_tr : dev(de))/|s_tr| - dl - (sqrt(2/3) g(dl, eps_n + dl) - |s_n|)/(2G) = 0
// by Peridigm's bisection on [0, 1] (its sign test and its stop |dl - dl_old|/|dl| < 1e-6, so that dl, and the
// stress, are Peridigm's to round-off: the stop leaves dl 1e-6 from the root; note eps_n + dl, not sqrt(2/3) dl, in
// the search, as Peridigm writes it), then the surface g(dl, eps_n + sqrt(2/3) dl) and, when sigma_vm,tr exceeds
// it, the return to it and the generic increment. A step of no length (dt <= 0) is elastic, as g is then infinite.
PeridigmJ2Step peridigmNeedleman(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G, double Y,
                                 const NeedlemanLaw& law, double dt);

}  // namespace pf
