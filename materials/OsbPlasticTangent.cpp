#include "OsbPlasticTangent.hpp"

#include <cmath>
#include <vector>

#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"
#include "OsbGradientCorrection.hpp"
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

// dSwx: d(sum omega x t^d_tr V), read only for the split along omega x (OsbJ2Constants::omegaSplit).
ReturnDerivative returnDerivative(const OsbTrialMoments& t, double dS2, double dSx, double dSwx, const OsbJ2Return& r,
                                  const OsbJ2Constants& k) {
  ReturnDerivative d{r.dlambda, r.G1, r.G2, r.pp, 0.0, 0.0, 0.0, 0.0};
  if (!(r.dlambda > 0.0)) return d;  // elastic: t^d = t^d_tr, no plastic extension
  if (k.omegaSplit) {                // pp = t^d_tr . x / m (OsbJ2OmegaSplit.hpp)
    d.dpp = dSx / t.Xw;
    d.ddlam = omegaSplitDeltaLambda(t, dS2, dSx, dSwx, r, k);
  } else {
    d.dpp = dSx / t.Xx;  // pp = t^d_tr . x / x . x
    d.ddlam = k.peridigmLaw ? peridigmDeltaLambda(t, dS2, r, k) : paperDeltaLambda(t, dS2, d.dpp, r, k);
  }
  d.dG1 = -d.G1 * d.G1 * k.bm * d.ddlam;  // G1 = 1 / (1 + bm dl)
  d.dG2 = k.peridigmLaw ? d.dG1 : -d.G2 * d.G2 * k.g2 * k.bm * d.ddlam;
  return d;
}

// Node i's state at y from its gathered family in scr (len, bond vectors, V_j; t^d_tr in scr.a from tr): its
// return and the dilatation of its force (for plane stress and 3D the plastic extension's, J2Flow::beta; plane strain
// keeps the trial dilatation, as the force does). False where the return mapping fails.
// PF_INLINE here and below: inlined into the kernels' target clones (avx512f, avx2), as the force kernel is. Left
// out of line, these were compiled for the baseline ISA only, and the 8-lane trial loops spilled to the stack: 4x
// the force kernel's time per call (BENCHMARKS.md "Consistent tangent").
PF_INLINE bool j2NodeLinearise(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const J2Fields& s,
                               int i, const osb::FamilyScratch& scr, const J2NodeTrial& tr, J2NodeTangent& nt) {
  const OsbConstants& c = p.osb;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const OsbJ2NodeState committed{s.lambdaN[i], s.alphaN[i], s.qN[i], s.signN[i]};
  nt.r = osbJ2ReturnMapping(tr.moments, committed, tr.k);
  if (nt.r.status != OsbJ2Status::Ok) return false;
  nt.theta = tr.thetaTr;
  const OsbJ2Return& r = nt.r;
  if (!(r.dlambda > 0.0) || !flow.beta) return true;
  // e^dp = e^dp_n + a1 (t^d_tr - pp x) + a2 x (Eqs. 52, 58), or a1 u (+ (a2 - a1 pp) x for the omega split)
  const double *xr = fam.refLength + b0, *w = fam.influence + b0, *epN = s.edpN + b0;
  const double *len = scr.len, *vj = scr.vj, *td = scr.a;
  const double a1 = r.dlambda * r.G1, a2 = r.dlambda * flow.phi * r.G2 * r.pp;
  const bool overOmega = !fam.unitInfluence && flow.flowOverOmega, omegaSplit = tr.k.omegaSplit;
  const double bm = tr.k.bm, cth = c.c * tr.thetaTr, ax = a2 - a1 * r.pp;
  double sum = 0.0;
  auto u = [&](int k) { return bm * (((len[k] - xr[k]) - cth * xr[k]) - epN[k]); };  // t^d_tr / omega
  for (int k = 0; k < n; ++k) {
    const double ep = omegaSplit  ? epN[k] + a1 * u(k) + ax * xr[k]
                      : overOmega ? epN[k] + a1 * u(k)
                                  : epN[k] + a1 * (td[k] - r.pp * xr[k]) + a2 * xr[k];
    sum += w[k] * xr[k] * ((len[k] - xr[k]) - ep) * vj[k];
  }
  nt.theta = c.k * c.D * sum / fam.weightedVolume[i];  // as the force kernel forms it (OsbJ2Node.hpp)
  return true;
}

// Node i's bond streams at one product: the family's (fam), the committed plastic extension, the gather at y in
// the scratch (bond vectors, lengths, V_j; t^d_tr in a) and the product's work arrays (de in b; dy_j - dy_i in
// g0..g2, then the reactions).
struct ProductStreams {
  const double *__restrict xr, *__restrict w, *__restrict epN;
  const double *__restrict d0, *__restrict d1, *__restrict d2, *__restrict len, *__restrict vj, *__restrict td;
  double *__restrict de, *__restrict e0, *__restrict e1, *__restrict e2;
};

// The direction's part of a node's derivative: d theta_tr and the plastic extension's coefficients,
// e^dp = e^dp_n + a1 (t^d_tr - pp x) + a2 x (Eqs. 52, 58) with its derivative da1, da2, dpp (d.*), and d theta.
// overOmega: e^dp = e^dp_n + a1 u, u = t^d_tr / omega (J2Flow::flowOverOmega), cth = c theta_tr; omegaSplit:
// e^dp = e^dp_n + a1 u + ax x, ax = a2 - a1 pp (OsbJ2OmegaSplit.hpp), with its derivative dax.
struct NodeDirection {
  double dthetaTr = 0.0, dtheta = 0.0, a1 = 0.0, a2 = 0.0, da1 = 0.0, da2 = 0.0, cth = 0.0, ax = 0.0, dax = 0.0;
  bool overOmega = false, omegaSplit = false;
  ReturnDerivative d{0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

// The plastic extension's increment e^dp - e^dp_n for the chunk at bond k (plastic nodes).
template <bool Unit, class Chunk>
PF_INLINE osb::Lanes plasticIncrement(const ProductStreams& b, const NodeDirection& nd, double bm, int k,
                                      const Chunk& ch) {
  if (!Unit && nd.omegaSplit)
    return nd.a1 * trialExtensionFlow(ch, b.xr, b.len, b.epN, bm, nd.cth, k) + nd.ax * ch.load(b.xr + k);
  if (!Unit && nd.overOmega) return nd.a1 * trialExtensionFlow(ch, b.xr, b.len, b.epN, bm, nd.cth, k);
  const osb::Lanes x = ch.load(b.xr + k);
  return nd.a1 * (ch.load(b.td + k) - nd.d.pp * x) + nd.a2 * x;
}

// d e^dp along the direction for the chunk at bond k (plastic nodes).
template <bool Unit, class Chunk>
PF_INLINE osb::Lanes plasticDerivative(const ProductStreams& b, const NodeDirection& nd, double bm, double cc, int k,
                                       const Chunk& ch, const osb::Lanes& dek) {
  const osb::Lanes x = ch.load(b.xr + k);
  if (!Unit && (nd.overOmega || nd.omegaSplit)) {  // d(a1 u (+ ax x)), du = bm (de - c d theta_tr x)
    const osb::Lanes dau = nd.da1 * trialExtensionFlow(ch, b.xr, b.len, b.epN, bm, nd.cth, k) +
                           nd.a1 * (bm * (dek - cc * nd.dthetaTr * x));
    return nd.omegaSplit ? dau + nd.dax * x : dau;
  }
  const osb::Lanes dtd = osb::weighted<Unit>(ch, b.w, k, dek - cc * nd.dthetaTr * x) * bm;
  return nd.da1 * (ch.load(b.td + k) - nd.d.pp * x) + nd.a1 * (dtd - nd.d.dpp * x) + nd.da2 * x;
}

// First pass: de = M . (dy_j - dy_i) (stored), d theta_tr (Eqs. 4/16 with e^dp_n fixed); with dt^d_tr = omega bm (de -
// c d theta_tr x) (Eqs. 40-41) the moments dP1 = 2 sum t^d dt^d V and d(t^d . x) follow from sums of this pass, and
// from them the return's derivative. Then, for plane stress and 3D, d theta of the plastic extension (J2Flow::beta).
// Padded lanes: y_j - y_i = 0, len 1 (the fill of a block's last family too), V_j 0: they add nothing.
// deGiven: de is in b.de already (the gradient correction's limited reading, j2NodeProduct), not M . (dy_j - dy_i).
template <bool Unit>
PF_INLINE NodeDirection j2NodeDirection(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, int i,
                                        const ProductStreams& b, const J2NodeTrial& tr, const OsbJ2Return& r,
                                        bool deGiven) {
  using osb::Lanes;
  const int n = fam.offsets[i + 1] - fam.offsets[i];
  const bool inBlock = osb::chunksStayInBlock(fam, i), plastic = r.dlambda > 0.0;
  const double invm = 1.0 / fam.weightedVolume[i], kD = p.osb.k * p.osb.D, bm = tr.k.bm, cc = p.osb.c;
  const bool omegaSplit = !Unit && tr.k.omegaSplit;
  Lanes S = {}, TdDe = {}, TdX = {}, WXX = {}, W2De = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto ch) {
    const Lanes x = ch.load(b.xr + k), v = ch.load(b.vj + k);
    Lanes dek;
    if (deGiven) {
      dek = osb::FullChunk{}.load(b.de + k);
    } else {
      dek = (ch.load(b.d0 + k) * ch.load(b.e0 + k) + ch.load(b.d1 + k) * ch.load(b.e1 + k) +
             ch.load(b.d2 + k) * ch.load(b.e2 + k)) / ch.load(b.len + k, 1.0);
      osb::FullChunk{}.store(b.de + k, dek);
    }
    const Lanes wv = osb::weighted<Unit>(ch, b.w, k, v);
    S += wv * x * dek;
    if (plastic) {
      const Lanes t = ch.load(b.td + k);
      TdDe += t * wv * dek;
      TdX += t * wv * x;
      WXX += wv * x * x;
      if (omegaSplit) W2De += osb::weighted<Unit>(ch, b.w, k, wv) * x * dek;
    }
  });
  NodeDirection nd;
  nd.overOmega = flow.flowOverOmega;
  nd.omegaSplit = omegaSplit;
  nd.cth = cc * tr.thetaTr;
  const double dsum = osb::laneSum(S);
  nd.dthetaTr = nd.dtheta = kD * dsum * invm;
  nd.d.pp = r.pp;
  if (!plastic) return nd;
  const double dS2 = 2.0 * bm * (osb::laneSum(TdDe) - cc * nd.dthetaTr * osb::laneSum(TdX));
  const double dSx = bm * (dsum - cc * nd.dthetaTr * osb::laneSum(WXX));
  // d(sum omega x t^d_tr V) = bm (sum omega^2 x de V - c d theta_tr sum omega^2 x^2 V): the omega split's moment
  const double dSwx = omegaSplit ? bm * (osb::laneSum(W2De) - cc * nd.dthetaTr * tr.moments.Xw2) : 0.0;
  const ReturnDerivative& d = nd.d = returnDerivative(tr.moments, dS2, dSx, dSwx, r, tr.k);  // Eqs. 47, 50
  nd.a1 = d.dlam * d.G1;
  nd.a2 = d.dlam * flow.phi * d.G2 * d.pp;
  nd.da1 = d.ddlam * d.G1 + d.dlam * d.dG1;
  nd.da2 = flow.phi * (d.ddlam * d.G2 * d.pp + d.dlam * d.dG2 * d.pp + d.dlam * d.G2 * d.dpp);
  if (omegaSplit) {  // ax = dlambda pp (phi G2 - G1)
    const double h = flow.phi * d.G2 - d.G1, dh = flow.phi * d.dG2 - d.dG1;
    nd.ax = nd.a2 - nd.a1 * d.pp;
    nd.dax = d.ddlam * d.pp * h + d.dlam * d.dpp * h + d.dlam * d.pp * dh;
  }
  if (flow.beta) {
    Lanes P = {};
    osb::forEachChunk(n, inBlock, [&](int k, auto ch) {
      const Lanes x = ch.load(b.xr + k), dek = osb::FullChunk{}.load(b.de + k);
      P += osb::weighted<Unit>(ch, b.w, k, x) * (dek - plasticDerivative<Unit>(b, nd, bm, cc, k, ch, dek)) *
           ch.load(b.vj + k);
    });
    nd.dtheta = kD * osb::laneSum(P) * invm;
  }
  return nd;
}

// Adds node i's part of dF along the direction whose records are dpos, with node i's family gathered in scr at y
// and its state nt: the direction pass, then the bond forces' derivative, scattered through the records as the force
// kernel's (addBondForces).
template <bool Unit>
PF_INLINE void j2NodeProduct(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const J2Fields& s, int i,
                             const osb::FamilyScratch& scr, const J2NodeTrial& tr, const J2NodeTangent& nt,
                             const double* fitRows, const osb::Quad* dpos, osb::Quad* dforce) {
  using osb::Lanes;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const ProductStreams b{fam.refLength + b0, fam.influence + b0, s.edpN + b0, scr.d0, scr.d1, scr.d2, scr.len,
                         scr.vj, scr.a, scr.b, scr.g0, scr.g1, scr.g2};
  osb::gatherDifferences(fam, dpos, i, b.e0, b.e1, b.e2);
  // A broken bond carries no force and so no derivative: its y_j - y_i is 0 (gatherFamily), its dy_j - dy_i too.
  if (fam.brokenN)
    for (int k = 0; k < n; ++k)
      if (fam.broken[b0 + k] != 0.0) b.e0[k] = b.e1[k] = b.e2[k] = 0.0;
  const bool quadratic = fitRows != nullptr;  // null: no correction, or a singular fit (the bonds read as they are)
  osb::CorrectedBonds& cb = osb::correctedBonds();
  if (quadratic) {
    // The reading's derivative: l = |Y| - g(|Y| - |Y'|) (OsbGradientCorrection.hpp, limitedCorrection), so
    // dl = (1 - g') M.dY + g' Y'.dY'/|Y'|, M.dY = d.dY / l (d = Y l/|Y|), dY' the direction's bond differences with the
    // kept fit's quadratic part taken out.
    for (int k = 0; k < n; ++k) cb.p0[k] = b.e0[k], cb.p1[k] = b.e1[k], cb.p2[k] = b.e2[k];
    if (p.dim != Dimension::ThreeD) osb::subtractKeptFit<5>(n, cb, fitRows, cb.p0.data(), cb.p1.data(), cb.p2.data());
    else osb::subtractKeptFit<9>(n, cb, fitRows, cb.p0.data(), cb.p1.data(), cb.p2.data());
    for (int k = 0; k < n; ++k) {
      const double mdy = (b.d0[k] * b.e0[k] + b.d1[k] * b.e1[k] + b.d2[k] * b.e2[k]) / b.len[k];
      const double lq = cb.lenQ[k];
      const double qdy = lq > 0.0 ? (cb.y0[k] * cb.p0[k] + cb.y1[k] * cb.p1[k] + cb.y2[k] * cb.p2[k]) / lq : 0.0;
      b.de[k] = mdy + cb.slope[k] * (qdy - mdy);
    }
    for (int k = n; k < osb::roundUpToLanes(n); ++k) b.de[k] = 0.0;
  }
  const NodeDirection nd = j2NodeDirection<Unit>(fam, p, flow, i, b, tr, nt.r, quadratic);
  // Force t = omega (iso theta x + dev (e - e^dp)) along M = Y/|Y| (Eqs. 7-13): d(t M) = dt M + t (I - M M^T) dY/|Y|
  // = (dt - t de/|Y|) Y/|Y| + (t/|Y|) dY. The reaction -dT V_i is stored negated (addBondForces).
  const bool plastic = nt.r.dlambda > 0.0;
  const double invm = 1.0 / fam.weightedVolume[i], cc = p.osb.c, bm = tr.k.bm;
  const double iso = (p.osb.A - tr.B * cc) * invm, dev = tr.B * invm, theta = nt.theta, mVi = -fam.volume[i];
  Lanes A0 = {}, A1 = {}, A2 = {};
  osb::forEachChunk(n, osb::chunksStayInBlock(fam, i), [&](int k, auto ch) {
    const Lanes x = ch.load(b.xr + k), v = ch.load(b.vj + k), dek = osb::FullChunk{}.load(b.de + k);
    const Lanes l = ch.load(b.len + k, 1.0), il = 1.0 / l;
    Lanes ep = ch.load(b.epN + k), dep = {};
    if (plastic) {
      ep += plasticIncrement<Unit>(b, nd, bm, k, ch);
      dep = plasticDerivative<Unit>(b, nd, bm, cc, k, ch, dek);
    }
    const Lanes t = osb::weighted<Unit>(ch, b.w, k, iso * theta * x + dev * ((l - x) - ep));
    const Lanes dt = osb::weighted<Unit>(ch, b.w, k, iso * nd.dtheta * x + dev * (dek - dep));
    Lanes along = (dt - t * dek * il) * il, across = t * il;
    if (quadratic) {  // direction Y/|Y| (uncorrected): d = Y l'/|Y|, so M.dY = d.dY / l'
      const Lanes lY = ch.load(cb.lenY.data() + k, 1.0), ilY = 1.0 / lY;
      const Lanes dekY = (ch.load(b.d0 + k) * ch.load(b.e0 + k) + ch.load(b.d1 + k) * ch.load(b.e1 + k) +
                          ch.load(b.d2 + k) * ch.load(b.e2 + k)) * il;
      along = (dt - t * dekY * ilY) * il;
      across = t * ilY;
    }
    const Lanes T0 = along * ch.load(b.d0 + k) + across * ch.load(b.e0 + k);
    const Lanes T1 = along * ch.load(b.d1 + k) + across * ch.load(b.e1 + k);
    const Lanes T2 = along * ch.load(b.d2 + k) + across * ch.load(b.e2 + k);
    A0 += T0 * v; A1 += T1 * v; A2 += T2 * v;
    osb::FullChunk{}.store(b.e0 + k, T0 * mVi); osb::FullChunk{}.store(b.e1 + k, T1 * mVi);
    osb::FullChunk{}.store(b.e2 + k, T2 * mVi);
  });
  osb::scatterReactions(fam, i, b.e0, b.e1, b.e2, osb::Quad{osb::laneSum(A0), osb::laneSum(A1), osb::laneSum(A2), 0.0},
                        dforce);
}

// Node i's family at y (pos) gathered into scr and its trial state. With the gradient correction, fitted here (the
// linearisation, which keeps the fit in tan) or with the coefficients kept (a product; a singular fit kept none).
template <bool Unit>
PF_INLINE J2NodeTrial j2NodeAt(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const J2Fields& s,
                               const osb::Quad* pos, int i, osb::FamilyScratch& scr, J2Tangent* keep,
                               const J2Tangent& kept) {
  osb::gatherFamily(fam, pos, i, scr);
  if (p.gradientCorrection) {
    const std::size_t at = static_cast<std::size_t>(i - fam.begin);
    const bool planar = p.dim != Dimension::ThreeD;
    if (keep)
      keep->fitKept[at] = osb::removeQuadratic<Unit>(fam, i, planar, scr, nullptr,
                                                     keep->fitQ.data() + at * osb::kMaxFitCoefficients,
                                                     keep->fitRows.data() + at * osb::kMaxFitRows);
    else if (kept.fitKept[at])
      osb::removeQuadratic<Unit>(fam, i, planar, scr, kept.fitQ.data() + at * osb::kMaxFitCoefficients);
  }
  return j2NodeTrial<Unit>(fam, p, flow, s.scf, s.edpN + fam.offsets[i], i, scr, scr.a);
}

template <bool Unit>
PF_INLINE bool j2Linearise(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s,
                           J2Tangent& tan) {
  const J2Flow flow = j2Flow(p);
  osb::FamilyScratch& scr = osb::familyScratch(fam);
  tan.pos = osb::positionRecords(fam, y, tan.records);
  const std::size_t owned = static_cast<std::size_t>(fam.end > fam.begin ? fam.end - fam.begin : 0);
  tan.node.resize(owned);
  if (p.gradientCorrection) {
    tan.fitKept.assign(owned, 0);
    tan.fitRows.resize(owned * osb::kMaxFitRows);
    tan.fitQ.resize(owned * osb::kMaxFitCoefficients);
  }
  for (int i = fam.begin; i < fam.end; ++i) {
    const J2NodeTrial tr = j2NodeAt<Unit>(fam, p, flow, s, tan.pos, i, scr, &tan, tan);
    if (!j2NodeLinearise(fam, p, flow, s, i, scr, tr, tan.node[i - fam.begin])) return false;
  }
  return true;
}

template <bool Unit>
PF_INLINE void j2TangentProduct(const FamilyView& fam, const J2Parameters& p, const J2Fields& s, const J2Tangent& tan,
                                const double* dy, double* dforce) {
  const J2Flow flow = j2Flow(p);
  osb::FamilyScratch& scr = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, dy, dforce);
  const bool prefetchRecords = osb::prefetchRecordsPays(fam, rec);
  for (int i = fam.begin; i < fam.end; ++i) {
    // As the force kernel (j2Force): the bond streams two nodes ahead, the neighbours' records one ahead (here the
    // positions y besides the direction's and the force's records).
    const int ahead = osb::prefetchFamily(fam, i);
    if (ahead >= 0) osb::prefetchBondRange(fam, ahead, s.edpN, false);
    if (prefetchRecords) osb::prefetchNeighbourRecords(fam, rec, i, tan.pos);
    const std::size_t at = static_cast<std::size_t>(i - fam.begin);
    const J2NodeTrial tr = j2NodeAt<Unit>(fam, p, flow, s, tan.pos, i, scr, nullptr, tan);
    const double* rows = p.gradientCorrection && tan.fitKept[at] ? tan.fitRows.data() + at * osb::kMaxFitRows : nullptr;
    j2NodeProduct<Unit>(fam, p, flow, s, i, scr, tr, tan.node[at], rows, rec.pos, rec.force);
  }
  osb::storeForces(fam, rec, dforce);
}

}  // namespace

std::size_t J2Tangent::bytes() const {
  return node.capacity() * sizeof(J2NodeTangent) + records.capacity() * sizeof(double) + fitKept.capacity() +
         (fitRows.capacity() + fitQ.capacity()) * sizeof(double);
}

PF_KERNEL_CLONES bool osbJ2Linearise(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s,
                                     J2Tangent& tan) {
  return fam.unitInfluence ? j2Linearise<true>(fam, p, y, s, tan) : j2Linearise<false>(fam, p, y, s, tan);
}

PF_KERNEL_CLONES void osbJ2TangentProduct(const FamilyView& fam, const J2Parameters& p, const J2Fields& s,
                                          const J2Tangent& tan, const double* dy, double* dforce) {
  if (fam.unitInfluence) j2TangentProduct<true>(fam, p, s, tan, dy, dforce);
  else j2TangentProduct<false>(fam, p, s, tan, dy, dforce);
}

PF_KERNEL_CLONES bool osbJ2ForceDerivative(const FamilyView& fam, const J2Parameters& p, const double* y,
                                           const double* dy, const J2Fields& s, double* dforce) {
  // The kept tangent, formed and applied once: one code path, so the two give the same bits.
  J2Tangent tan;
  if (!osbJ2Linearise(fam, p, y, s, tan)) return false;
  osbJ2TangentProduct(fam, p, s, tan, dy, dforce);
  return true;
}

}  // namespace pf
