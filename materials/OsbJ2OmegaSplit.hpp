#pragma once
// The plane-stress return of the OSB J2 solid for a non-unit influence function (OsbJ2Constants::omegaSplit):
// t^d_tr split along omega x instead of x, the moments that split needs, the yield function of the returned state
// and its derivative for the consistent tangent. Internal to materials/ (docs/materials.md, limitation iii).
//
// Why: in plane stress the flow changes theta (beta, phi = 2), and the -c theta x feedback acts along omega x. With
// t^d = t_perp + pp omega x, sum x t_perp V = 0 (pp = t^d.x / m, m = sum omega x^2 V) and the flow (Eq. 52 divided
// by omega, as in 3D and plane strain)
//   e^dp_n+1 = e^dp_n + dlambda (t_perp,n+1 / omega + phi pp_n+1 x) = e^dp_n + a1 u + (a2 - a1 pp) x,
//   u = t^d_tr / omega, a1 = dlambda G1, a2 = dlambda phi G2 pp,
// theta moves by -k D dlambda phi G2 pp (t_perp drops out of sum omega x e^dp V), so t_perp decays by G1 (Eq. 47) and
// pp by G2 = 1/(1 + g2 bm dlambda), g2 = phi (1 - c k D), the constants of omega = 1. The stored state is exactly
// G1 t_perp + G2 pp omega x; only its moments change: t_perp is orthogonal to x but not to omega x, so
//   2 psi = G1^2 P_perp + G1 G2 P_c + G2^2 P_par,  P_perp = |t_perp|^2, P_c = 2 pp t_perp . omega x,
//   P_par = pp^2 m2 + 2 a2 (t^d.x)^2,  m2 = sum omega^2 x^2 V   (Eq. 31; t^d_n+1 . x = G2 t^d_tr . x).
// For omega = 1 (m2 = m = x.x, P_c = 0) this is the x split of J2ReturnMapping.hpp and Eq. 52 with phi.
#include <cmath>

#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"

namespace pf {

namespace {

// The trial state split along omega x, with psi(G1, G2) of the returned state and its dlambda derivative
// (dG1 = -bm G1^2, dG2 = -g2 bm G2^2) for the Newton of returnToYieldSurface.
struct OmegaSplit {
  double pp, Pperp, Pc, Ppar, vm;
  PF_INLINE double psi(double G1, double G2) const { return 0.5 * (G1 * G1 * Pperp + G1 * G2 * Pc + G2 * G2 * Ppar); }
  PF_INLINE double dpsi(double G1, double G2, double bm, double g2) const {
    return -bm * (G1 * G1 * G1 * Pperp + 0.5 * G1 * G2 * (G1 + g2 * G2) * Pc + g2 * G2 * G2 * G2 * Ppar);
  }
};

PF_INLINE OmegaSplit splitAlongOmegaX(const OsbTrialMoments& t, const OsbYieldConstants& yc) {
  const double pp = t.Sx / t.Xw;
  const double Pperp = t.S2 - 2.0 * pp * t.Swx + pp * pp * t.Xw2;  // sum (t - pp omega x)^2 V
  const double Pc = 2.0 * pp * (t.Swx - pp * t.Xw2);
  const double Ppar = pp * pp * t.Xw2 + 2.0 * yc.a2 * t.Sx * t.Sx;
  const double psiTr = 0.5 * t.S2 + yc.a2 * t.Sx * t.Sx;  // Eq. 31 directly: no cancellation in the trial value
  return {pp, Pperp, Pc, Ppar, std::sqrt(psiTr / yc.Cy)};
}

// The moments of the split from the trial state tdv (trialDeviatoricState): Swx = sum omega x t^d V, Xw2 = sum omega^2
// x^2 V; Xw = m, the weighted volume the dilatation divides by (so that t_perp drops out of theta's change).
template <bool Unit>
PF_INLINE void omegaSplitMoments(const double* __restrict w, const double* __restrict xr, const double* __restrict vj,
                                 const double* __restrict tdv, int n, bool inBlock, double m, OsbTrialMoments& t) {
  osb::Lanes Swx = {}, Xw2 = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) {
    const osb::Lanes wx = osb::weighted<Unit>(c, w, k, c.load(xr + k)), v = c.load(vj + k);
    Swx += wx * osb::FullChunk{}.load(tdv + k) * v;
    Xw2 += wx * wx * v;
  });
  t.Swx = osb::laneSum(Swx);
  t.Xw2 = osb::laneSum(Xw2);
  t.Xw = m;
}

// d dlambda of the omega split's return along a direction with trial moments changing by dS2, dSx, dSwx (the
// consistency condition F = sigma_vm - sigma_bar_n - (K + H) |d eps_p| = 0 at the converged root, differentiated as
// OsbPlasticTangent.cpp's paperDeltaLambda does for the x split; Xw, Xw2 are reference quantities).
inline double omegaSplitDeltaLambda(const OsbTrialMoments& t, double dS2, double dSx, double dSwx, const OsbJ2Return& r,
                                    const OsbJ2Constants& k) {
  const OsbYieldConstants& yc = k.yield;
  const OmegaSplit s = splitAlongOmegaX(t, yc);
  const double pp = s.pp, dpp = dSx / t.Xw, KH = k.isoHardening + k.kinHardening;
  const double dPperp = dS2 - 2.0 * (dpp * t.Swx + pp * dSwx) + 2.0 * pp * dpp * t.Xw2;
  const double dPc = 2.0 * (dpp * t.Swx + pp * dSwx) - 4.0 * pp * dpp * t.Xw2;
  const double dPpar = 2.0 * pp * dpp * t.Xw2 + 4.0 * yc.a2 * t.Sx * dSx;
  const double G1 = r.G1, G2 = r.G2, dl = r.dlambda;
  const double psi = s.psi(G1, G2), root = std::sqrt(yc.Ce * psi);
  const double Fpsi = 1.0 / (2.0 * std::sqrt(yc.Cy * psi)) - KH * dl * yc.Ce / (2.0 * root);
  const double Fdl = Fpsi * s.dpsi(G1, G2, k.bm, k.g2) - KH * root;
  return -Fpsi * 0.5 * (G1 * G1 * dPperp + G1 * G2 * dPc + G2 * G2 * dPpar) / Fdl;
}

}  // namespace

}  // namespace pf
