#pragma once
// The J2 stress updates of Peridigm's "Elastic Plastic Correspondence" and "Isotropic Hardening Correspondence"
// (src/materials/elastic_plastic_correspondence.cxx, isotropic_hardening_correspondence.cxx), on the unrotated
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

}  // namespace pf
