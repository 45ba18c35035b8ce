#pragma once
// The Drucker-Prager update of Li & Geng (seed 003, Section 4.3 and Appendix) on the unrotated Cauchy stress:
// yield f = J - m (A I + B), potential g = J - m d0 A I - m B (Eq. 38), J = sqrt(s:s / 2), hyperbolic
// hardening m(xi) = m0 + h (1 - m0) xi / (1 - m0 + h xi) (Eq. A14; Eq. 39 as printed lacks the factor xi),
// elastic predictor (Eqs. 40-41, A1-A3) and a backward-Euler closest-point return (Eqs. 43-47, A4-A18),
// with a return to the cone's apex (the paper has none) when the cone return would end past it.
//
// Sign convention: the paper's I (first invariant) and s are compression positive; the code's stresses
// are tension positive. Here I = -tr(tau) and s = -dev(tau) internally; tau in and out is tension positive.
// Scalar functions on plain values; the only throw is ConstitutiveFailure (no convergence).
#include "core/Tensor3.hpp"

namespace pf {

struct DruckerPragerLaw {
  double A;          // A^phi = 2 sin(phi) / (sqrt(3) (3 - sin(phi)))      (Eq. 38)
  double B;          // B^phi = 6 c cos(phi) / (sqrt(3) (3 - sin(phi)))    (Eq. 38)
  double m0;         // initial hardening parameter, in (0, 1]
  double h;          // hardening rate, >= 0 (0: perfectly plastic, m = m0)
  double d0;         // dilatancy ratio in [0, 1] (1: associated flow)
};

// A, B of Eq. 38 from the friction angle [degrees] and the cohesion.
DruckerPragerLaw druckerPragerLaw(double frictionDegrees, double cohesion, double m0, double h, double d0);

// m(xi) of Eq. A14.
double druckerPragerHardening(const DruckerPragerLaw& law, double xi);

// The coefficients B1..B4 of the cubic Eq. A15 in dlambda (Eqs. A16-A17) with the misprint of B4
// corrected: its first term is alpha13^2 J_trial (the paper prints alpha13 J_trial). iTrial, jTrial are
// the paper's compression-positive I and J of the trial stress, xiN the committed PIV, K and G the moduli.
// The cubic is the consistency condition f = 0 times (alpha13 + alpha14 dlambda)^2; the update solves the
// condition itself (same root), this is for checking.
void druckerPragerCubic(const DruckerPragerLaw& law, double K, double G, double iTrial, double jTrial, double xiN,
                        double b[4]);

struct DruckerPragerStep {
  Mat3 tau;          // unrotated Cauchy stress at the step's end (tension positive)
  double xi;         // plastic internal variable: the equivalent plastic strain of Eq. 47, xi += dlambda / 2 (A13)
  double m;          // hardening parameter m(xi) (A14)
  double dlambda;    // plastic multiplier of the step (0: elastic)
  bool apex;         // the step returned to the apex (J = 0, I = -B/A)
  int iterations;    // of the scalar solve (0: elastic or apex)
};

// The yield function f = J - m (A I + B) of the stress tau (tension positive) at hardening m, divided by the
// yield surface's J at the same pressure magnitude, m (A |I| + B): dimensionless, J / J_yield - 1 under
// compression, 0 on the surface, > 0 outside (the "Yield_Function" output and the loading-balance
// correction's test). Where that scale is 0 (B = 0 and I = 0) it is 1 for J > 0 and 0 for J = 0.
double druckerPragerYieldRatio(const DruckerPragerLaw& law, const Mat3& tau, double m);

// One step from the committed tauN, xiN with the unrotated strain increment de, bulk modulus K, shear
// modulus G. Elastic when f(trial, m_n) <= 0 (Eq. 41); else the cone return: the consistency condition
//   J_tr - G dl - m(dl) (A (I_tr + 9 K A d0 m(dl) dl) + B) = 0,  m(dl) = m(xiN + dl/2)   (Eqs. A9, A10, A13, A14)
// solved for dl on [0, J_tr/G] (J_n+1 = J_tr - G dl >= 0, Eq. A10) by Newton's method safeguarded by
// bisection; if the condition has no root there (the return would pass J = 0), the apex return:
// tau = the apex (I = -B/A, J = 0, independent of m), xi += J_tr / (2 G) (Eq. 47 with the deviatoric
// plastic strain s_tr / (2 G)).
DruckerPragerStep druckerPragerUpdate(const DruckerPragerLaw& law, double K, double G, const Mat3& tauN, double xiN,
                                      const Mat3& de);

}  // namespace pf
