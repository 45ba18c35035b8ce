#include "OsbPlasticTangent.hpp"

#include <cmath>

#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"
#include "OsbJ2Trial.hpp"

namespace pf {

namespace {

// The return mapping's outputs (Eq. 47 per part, Eq. 52) and their derivatives along dy.
struct ReturnDerivative {
  double dlam, G1, G2, pp;  // at y (OsbJ2Return)
  double ddlam, dG1, dG2, dpp;
};

// d dlambda from the consistency condition F(dlambda; Pperp, Ppar) = 0 differentiated at the converged root
// (implicit function theorem): dF = F_dl ddl + F_psi dpsi|_dl = 0, F = sigma_vm - sigma_bar_n - (K + H) |d eps_p|
// as the return solves it (Eqs. 50, 55-57 with sigma_bar = sigma_bar_n + (K + H) |d eps_p|). sigma_bar_n, the
// sign of sigma_vm and sign(sigma_vm - q) are piecewise constant in y (committed values and signs), so they
// carry no derivative. Pperp is clipped at 0 in the return; where the clip is active its derivative is 0.
double paperDeltaLambda(const OsbTrialMoments& t, double dS2, double dpp, const OsbJ2Return& r,
                        const OsbJ2Constants& k) {
  const OsbYieldConstants& yc = k.yield;
  const double pp = r.pp, Xx = t.Xx, KH = k.isoHardening + k.kinHardening;
  const double PperpRaw = t.S2 - pp * pp * t.Xx;
  const double Pperp = PperpRaw > 0.0 ? PperpRaw : 0.0;
  const double dPperp = PperpRaw > 0.0 ? dS2 - 2.0 * pp * dpp * Xx : 0.0;
  const double Ppar = pp * pp * Xx * (1.0 + 2.0 * yc.a2 * Xx);
  const double dPpar = 2.0 * pp * dpp * Xx * (1.0 + 2.0 * yc.a2 * Xx);
  const double G1 = r.G1, G2 = r.G2, dl = r.dlambda;
  const double psi = 0.5 * (G1 * G1 * Pperp + G2 * G2 * Ppar);
  const double root = std::sqrt(yc.Ce * psi);
  const double Fpsi = 1.0 / (2.0 * std::sqrt(yc.Cy * psi)) - KH * dl * yc.Ce / (2.0 * root);
  const double psiDl = -k.bm * (G1 * G1 * G1 * Pperp + k.g2 * G2 * G2 * G2 * Ppar);  // as the return's dpsi
  const double Fdl = Fpsi * psiDl - KH * root;
  return -Fpsi * 0.5 * (G1 * G1 * dPperp + G2 * G2 * dPpar) / Fdl;
}

// Peridigm's law (PeridigmHardening.hpp): g(dl) = S2 / (2 (1 + bm dl)^2) - psi0 - H (lambda_n + dl) = 0, whose
// root its closed form (or Newton) returns; differentiated the same way. H = 0 gives the derivative of its
// perfectly plastic closed form dl = (|t^d| / sqrt(2 psi0) - 1) / bm.
double peridigmDeltaLambda(const OsbTrialMoments& t, double dS2, const OsbJ2Return& r, const OsbJ2Constants& k) {
  const double G = r.G1;
  const double gdl = -t.S2 * k.bm * G * G * G - k.peridigmH;
  return -0.5 * G * G * dS2 / gdl;
}

ReturnDerivative returnDerivative(const OsbTrialMoments& t, double dS2, double dSx, const OsbJ2Return& r,
                                  const OsbJ2Constants& k) {
  ReturnDerivative d{r.dlambda, r.G1, r.G2, r.pp, 0.0, 0.0, 0.0, 0.0};
  if (!(r.dlambda > 0.0)) return d;  // elastic: t^d = t^d_tr, no plastic extension
  d.dpp = dSx / t.Xx;                // pp = t^d_tr . x / x . x
  d.ddlam = k.peridigmLaw ? peridigmDeltaLambda(t, dS2, r, k) : paperDeltaLambda(t, dS2, d.dpp, r, k);
  d.dG1 = -d.G1 * d.G1 * k.bm * d.ddlam;  // G1 = 1 / (1 + bm dl)
  d.dG2 = k.peridigmLaw ? d.dG1 : -d.G2 * d.G2 * k.g2 * k.bm * d.ddlam;
  return d;
}

// Node i: gathered family in scr (len, bond vectors, V_j), t^d_tr in scr.a; uses g0..g2 as work arrays.
// Elastic nodes (most of a body) take only the first and the last bond pass.
// PF_INLINE here and below: inlined into osbJ2ForceDerivative's target clones (avx512f, avx2), as the force
// kernel is. Left out of line, these were compiled for the baseline ISA only, and the 8-lane trial loops spilled
// to the stack: 4x the force kernel's time per call (BENCHMARKS.md "Consistent tangent").
template <bool Unit>
PF_INLINE bool j2NodeDerivative(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const double* dy,
                      const J2Fields& s, int i, const osb::FamilyScratch& scr, double* dforce) {
  const OsbConstants& c = p.osb;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* nbr = fam.neighbors + b0;
  const double *xr = fam.refLength + b0, *w = fam.influence + b0, *epN = s.edpN + b0;
  const double *len = scr.len, *vj = scr.vj, *td = scr.a;
  double *de = scr.g0, *il = scr.g1, *dep = scr.g2;
  const double m = fam.weightedVolume[i], invm = 1.0 / m, kD = c.k * c.D;
  const J2NodeTrial tr = j2NodeTrial<Unit>(fam, p, flow, s.scf, epN, i, scr, scr.a);
  const OsbJ2NodeState committed{s.lambdaN[i], s.alphaN[i], s.qN[i], s.signN[i]};
  const OsbJ2Return r = osbJ2ReturnMapping(tr.moments, committed, tr.k);
  if (r.status != OsbJ2Status::Ok) return false;
  const bool plastic = r.dlambda > 0.0;
  const double bm = tr.k.bm, cc = c.c;
  // Trial part: de = M . (dy_j - dy_i), d theta_tr (Eqs. 4/16 with e^dp_n fixed); with dt^d_tr = omega bm (de -
  // c d theta_tr x) (Eqs. 40-41) the moments dP1 = 2 sum t^d dt^d V and d(t^d . x) follow from four sums of this pass.
  double dsum = 0.0, tdDe = 0.0, tdX = 0.0, wXX = 0.0;
  for (int k = 0; k < n; ++k) {
    const double* a = dy + 3 * nbr[k];
    const double* b = dy + 3 * i;
    il[k] = 1.0 / len[k];
    de[k] = (scr.d0[k] * (a[0] - b[0]) + scr.d1[k] * (a[1] - b[1]) + scr.d2[k] * (a[2] - b[2])) * il[k];
    const double wv = w[k] * vj[k];
    dsum += wv * xr[k] * de[k];
    if (plastic) {
      tdDe += td[k] * wv * de[k];
      tdX += td[k] * wv * xr[k];
      wXX += wv * xr[k] * xr[k];
    }
  }
  const double dthetaTr = kD * dsum * invm;
  double theta = tr.thetaTr, dtheta = dthetaTr;
  ReturnDerivative d{0.0, 1.0, 1.0, r.pp, 0.0, 0.0, 0.0, 0.0};
  double a1 = 0.0, a2 = 0.0;
  if (plastic) {
    const double dS2 = 2.0 * bm * (tdDe - cc * dthetaTr * tdX), dSx = bm * (dsum - cc * dthetaTr * wXX);
    // Return mapping (Eqs. 47, 50); plastic extension e^dp = e^dp_n + a1 (t^d_tr - pp x) + a2 x (Eqs. 52, 58).
    d = returnDerivative(tr.moments, dS2, dSx, r, tr.k);
    a1 = d.dlam * d.G1;
    a2 = d.dlam * flow.phi * d.G2 * d.pp;
    const double da1 = d.ddlam * d.G1 + d.dlam * d.dG1;
    const double da2 = flow.phi * (d.ddlam * d.G2 * d.pp + d.dlam * d.dG2 * d.pp + d.dlam * d.G2 * d.dpp);
    double sum = 0.0, dsumP = 0.0;
    for (int k = 0; k < n; ++k) {
      const double dtd = w[k] * bm * (de[k] - cc * dthetaTr * xr[k]);
      const double ep = epN[k] + a1 * (td[k] - d.pp * xr[k]) + a2 * xr[k];
      dep[k] = da1 * (td[k] - d.pp * xr[k]) + a1 * (dtd - d.dpp * xr[k]) + da2 * xr[k];
      sum += w[k] * xr[k] * ((len[k] - xr[k]) - ep) * vj[k];
      dsumP += w[k] * xr[k] * (de[k] - dep[k]) * vj[k];
    }
    // Plane strain keeps the trial (total-extension) dilatation (J2Flow::beta), as the force does.
    if (flow.beta) {
      theta = kD * sum * invm;
      dtheta = kD * dsumP * invm;
    }
  }
  // Force t = omega (iso theta x + dev (e - e^dp)) along M = Y/|Y| (Eqs. 7-13): d(t M) = dt M + t (I - M M^T) dY/|Y|
  // = (dt - t de/|Y|) Y/|Y| + (t/|Y|) dY.
  const double iso = (c.A - tr.B * cc) * invm, dev = tr.B * invm;
  const double* V = fam.volume;
  for (int k = 0; k < n; ++k) {
    if (fam.brokenN && fam.broken[b0 + k] != 0.0) continue;  // no force, no derivative (gatherFamily)
    const int j = nbr[k];
    const double ep = plastic ? epN[k] + a1 * (td[k] - d.pp * xr[k]) + a2 * xr[k] : epN[k];
    const double dp = plastic ? dep[k] : 0.0;
    const double t = w[k] * (iso * theta * xr[k] + dev * ((len[k] - xr[k]) - ep));
    const double dt = w[k] * (iso * dtheta * xr[k] + dev * (de[k] - dp));
    const double along = (dt - t * de[k] * il[k]) * il[k], across = t * il[k];
    const double Vi = fam.fraction ? V[i] * fam.fraction[b0 + k] : V[i];  // as addBondForces
    const double Y[3] = {scr.d0[k], scr.d1[k], scr.d2[k]};
    for (int e = 0; e < 3; ++e) {
      const double dT = along * Y[e] + across * (dy[3 * j + e] - dy[3 * i + e]);
      dforce[3 * i + e] += dT * vj[k];
      dforce[3 * j + e] -= dT * Vi;
    }
  }
  return true;
}

template <bool Unit>
PF_INLINE bool j2Derivative(const FamilyView& fam, const J2Parameters& p, const double* y, const double* dy, const J2Fields& s,
                  double* dforce) {
  const J2Flow flow = j2Flow(p);
  osb::FamilyScratch& scr = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, nullptr);
  for (int i = fam.begin; i < fam.end; ++i) {
    osb::gatherFamily(fam, rec.pos, i, scr);
    if (!j2NodeDerivative<Unit>(fam, p, flow, dy, s, i, scr, dforce)) return false;
  }
  return true;
}

}  // namespace

PF_KERNEL_CLONES bool osbJ2ForceDerivative(const FamilyView& fam, const J2Parameters& p, const double* y,
                                           const double* dy, const J2Fields& s, double* dforce) {
  return fam.unitInfluence ? j2Derivative<true>(fam, p, y, dy, s, dforce) : j2Derivative<false>(fam, p, y, dy, s, dforce);
}

}  // namespace pf
