#pragma once
// The per-node update of the OSB J2 solid (Pirzadeh et al. 2024 §3.2): the return mapping (J2ReturnMapping.hpp),
// inlined, and node i's trial state, return, plastic extension, node state and force from its gathered family
// (j2Node). Shared by the force kernel (OsbPlasticKernels.cpp) and its thermal twin (OsbThermalPlasticKernels.cpp),
// each compiled into its own target clones. Internal to materials/: the functions keep the internal linkage (an
// unnamed namespace) they had in OsbPlasticKernels.cpp, so each kernel source inlines its own copy.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Material.hpp"
#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"
#include "OsbJ2OmegaSplit.hpp"
#include "OsbJ2Trial.hpp"
#include "PeridigmHardening.hpp"

namespace pf {

// ---- The per-node return mapping (J2ReturnMapping.hpp) ----

namespace {

// sigma_vm of t^d_tr from the split t^d = t_perp + pp x with t_perp . x = 0: the two parts decay at
// different rates in plane stress, and only pp enters the 2D (t.x)^2 term. Pperp = |t_perp|^2, Ppar =
// the 2 psi of pp x (Eq. 31).
struct TrialSplit {
  double pp, Pperp, Ppar, vm;
  // psi of the returned state G1 t_perp + G2 pp x and its dlambda derivative (dG1 = -bm G1^2, dG2 = -g2 bm G2^2)
  PF_INLINE double psi(double G1, double G2) const { return 0.5 * (G1 * G1 * Pperp + G2 * G2 * Ppar); }
  PF_INLINE double dpsi(double G1, double G2, double bm, double g2) const {
    return -bm * (G1 * G1 * G1 * Pperp + g2 * G2 * G2 * G2 * Ppar);
  }
};

PF_INLINE TrialSplit splitTrial(const OsbTrialMoments& t, const OsbYieldConstants& yc) {
  const double pp = t.Sx / t.Xx;
  const double Pperp = std::max(t.S2 - pp * pp * t.Xx, 0.0);  // std::fmax is a libm call
  const double Ppar = pp * pp * t.Xx * (1.0 + 2.0 * yc.a2 * t.Xx);
  const double psiTr = 0.5 * (Pperp + Ppar);
  return {pp, Pperp, Ppar, std::sqrt(psiTr / yc.Cy)};  // Eq. 20 (3D with /2, see design doc), 2D analogue
}

// Sign of sigma_vm: third moment of t^d (analogue of J3); kept from the last step when it vanishes
// (pure shear), +1 for a virgin point.
PF_INLINE double vonMisesSign(const OsbTrialMoments& t, double committedSign) {
  double sgn = committedSign != 0.0 ? committedSign : 1.0;
  if (t.S3 > 1e-8 * std::fabs(t.A3)) sgn = 1.0;
  else if (t.S3 < -1e-8 * std::fabs(t.A3)) sgn = -1.0;
  return sgn;
}

// Sign of sigma_vm along the committed plastic extension (OsbJ2SignRule::PlasticExtension): + while the
// trial state points along e^dp_n, - against it; + for a node that has not flowed (its first flow sets e^dp).
PF_INLINE double plasticExtensionSign(const OsbTrialMoments& t) { return t.Se < 0.0 ? -1.0 : 1.0; }

struct NewtonResult {
  double dlam, G1, G2, vm, deps;
  int iters;
  bool converged;
};

// Plastic trial state (f(t^d_tr) > 0, Eq. 43): Newton on Eq. 50 written as sqrt(psi/Cy) = sigma_bar (same
// root, better scaled), with alpha and q following Eqs. 55-57 so sigma_bar = sigma_bar_n + (K + H) |d eps_p|.
// Split: TrialSplit (along x) or OmegaSplit (along omega x, OsbJ2OmegaSplit.hpp), psi(G1, G2) of the returned state.
template <class Split>
PF_INLINE NewtonResult returnToYieldSurface(const Split& tr, double sbarN, const OsbJ2Constants& k) {
  const OsbYieldConstants& yc = k.yield;
  const double bm = k.bm, g2 = k.g2, vmTr = tr.vm;
  const double KH = k.isoHardening + k.kinHardening;
  // Initial guess: exact when G1 = G2 (3D, plane strain), where the return is radial with slope
  // bm/(2 Cy) (= 3 mu for the discrete normalisation).
  const double e0 = (vmTr - sbarN) / (bm / (2.0 * yc.Cy) + KH);
  double dlam = e0 / (2.0 * yc.Cy * (sbarN + KH * e0)), G1, G2, vm, deps;
  int iters = 0;
  for (;;) {
    G1 = 1.0 / (1.0 + bm * dlam);
    G2 = 1.0 / (1.0 + g2 * bm * dlam);
    const double psi = tr.psi(G1, G2);
    const double dpsi = tr.dpsi(G1, G2, bm, g2);
    const double root = std::sqrt(yc.Ce * psi);
    vm = std::sqrt(psi / yc.Cy);
    deps = dlam * root;
    const double F = vm - sbarN - KH * deps;
    if (std::fabs(F) <= k.tolerance * vmTr) return {dlam, G1, G2, vm, deps, iters, true};
    if (iters == k.maxIterations) return {dlam, G1, G2, vm, deps, iters, false};
    const double dF = dpsi / (2.0 * std::sqrt(yc.Cy * psi)) - KH * (root + dlam * yc.Ce * dpsi / (2.0 * root));
    dlam -= F / dF;
    if (dlam < 0.0) dlam = 0.0;
    ++iters;
  }
}

// Peridigm's law (elastic_plastic_hardening.cxx, 3D): dlambda from its cubic, t^d_n+1 = t^d_tr / (1 + bm
// dlambda) for every bond (G1 = G2), yield value psi0 = Cy sigma_y0^2 raised by H lambda. Von Mises and the
// equivalent plastic strain are reported as the paper defines them (Eqs. 20, 55), for output only.
PF_INLINE OsbJ2Return peridigmReturn(const OsbTrialMoments& t, const OsbJ2NodeState& n, const OsbJ2Constants& k) {
  const double psi0 = k.yield.Cy * k.yieldStress * k.yieldStress;
  const double dl = peridigmDeltaLambda(std::sqrt(t.S2), n.lambda, psi0, k.bm, k.peridigmH);
  const double G = 1.0 / (1.0 + k.bm * dl);
  OsbJ2Return r{};
  r.pp = t.Sx / t.Xx;
  r.vonMisesTrial = std::sqrt(0.5 * t.S2 / k.yield.Cy);
  r.yieldLevel = std::sqrt((psi0 + k.peridigmH * n.lambda) / k.yield.Cy);
  r.dlambda = dl;
  r.G1 = r.G2 = G;
  r.vonMises = G * r.vonMisesTrial;
  r.plasticStrain = dl * G * std::sqrt(k.yield.Ce * 0.5 * t.S2);
  r.state = {n.lambda + dl, n.alpha + r.plasticStrain, n.q, vonMisesSign(t, n.sign)};
  r.status = OsbJ2Status::Ok;
  return r;
}

// The return for the trial state's split (TrialSplit or OmegaSplit).
template <class Split>
PF_INLINE OsbJ2Return returnAlong(const Split& tr, const OsbTrialMoments& trial, const OsbJ2NodeState& committed,
                                  const OsbJ2Constants& k) {
  const double thirdMomentSign = vonMisesSign(trial, committed.sign);
  double sgn = thirdMomentSign;  // OsbJ2SignRule
  if (k.signRule == OsbJ2SignRule::PlasticExtension) sgn = plasticExtensionSign(trial);
  else if (k.signRule == OsbJ2SignRule::CommittedThirdMoment && committed.q != 0.0)
    sgn = committed.sign < 0.0 ? -1.0 : 1.0;
  // Direction of plastic flow along the loading axis, sign(sigma_vm - q) of Eqs. 45-46, 56.
  const double dir = sgn * tr.vm - committed.q >= 0.0 ? 1.0 : -1.0;
  // Current yield level, Eqs. 39/46 (not Eq. 32, which drops q after the sign).
  const double sigmaBar = k.yieldStress + k.isoHardening * committed.alpha;
  const double sbarN = sigmaBar + dir * committed.q;
  OsbJ2Return r{};
  r.pp = tr.pp;
  r.vonMisesTrial = tr.vm;
  r.yieldLevel = sbarN;
  if (!(sbarN > 0.0)) {  // the scalar back stress has no meaning beyond the yield level
    r.status = OsbJ2Status::BackStressBeyondYield;
    return r;
  }
  // f = |sgn vm - q| - sigma_bar (Eqs. 45-46) > 0 is vm > sbarN only while sgn = dir. When they differ, the state
  // went back past the centre q along its own direction (vm < |q|, e.g. a hardened point unloading), and f > 0
  // would need |q| > sigma_bar + vm, which sbarN > 0 excludes: elastic. Until 2026-12-06 such states were returned
  // to sbarN as if plastic whenever vm > sigma_bar - |q|: a spurious yield on unloading once |q| > sigma_bar/2,
  // which stopped the kinematic cylinder's unloading (docs/verification.md).
  const bool pastCentre = sgn != dir;
  NewtonResult nr{0.0, 1.0, 1.0, tr.vm, 0.0, 0, true};  // elastic: t^d_n+1 = t^d_tr
  if (!pastCentre && tr.vm > sbarN) nr = returnToYieldSurface(tr, sbarN, k);  // f(t^d_tr) > 0, Eqs. 42-43
  r.iterations = nr.iters;
  if (!nr.converged) {
    r.status = OsbJ2Status::NotConverged;
    return r;
  }
  r.state.lambda = committed.lambda + nr.dlam;
  r.state.alpha = committed.alpha + nr.deps;                    // Eq. 57
  r.state.q = committed.q + dir * k.kinHardening * nr.deps;     // Eq. 56
  r.state.sign = thirdMomentSign;
  r.dlambda = nr.dlam;
  r.G1 = nr.G1;
  r.G2 = nr.G2;
  r.plasticStrain = nr.deps;
  r.vonMises = nr.vm;
  r.status = OsbJ2Status::Ok;
  return r;
}

// The body of osbJ2ReturnMapping, inlined into each clone of the kernel. As a call per node it made the J2
// kernel execute 1.1 % more instructions (callgrind, AVX2 clone, 16^3 hardening cube; inlined: +0.15 %)
// and run ~5 % slower on bench/kernel_hardening_40.xml (noisy host).
PF_INLINE OsbJ2Return returnMapping(const OsbTrialMoments& trial, const OsbJ2NodeState& committed,
                                    const OsbJ2Constants& k) {
  if (k.peridigmLaw) return peridigmReturn(trial, committed, k);
  if (k.omegaSplit) return returnAlong(splitAlongOmegaX(trial, k.yield), trial, committed, k);
  return returnAlong(splitTrial(trial, k.yield), trial, committed, k);
}

}  // namespace

// ---- The per-node update: trial state, return mapping, plastic extension, node state, force ----

namespace {

[[noreturn]] void throwReturnFailure(const OsbJ2Return& r, double committedQ, int maxIterations, int i) {
  std::ostringstream msg;
  if (r.status == OsbJ2Status::BackStressBeyondYield)
    msg << "J2 return mapping: back stress " << committedQ << " exceeds the yield level at node " << i
        << "; the scalar kinematic hardening model does not cover this state";
  else
    msg << "J2 return mapping did not converge in " << maxIterations << " iterations at node " << i
        << " (trial von Mises " << r.vonMisesTrial << ", yield level " << r.yieldLevel << ")";
  throw ConstitutiveFailure(msg.str());
}

// Writes the new plastic extension e^dp_n+1 = extension(k, chunk) of each chunk to ep and returns the dilatation
// sum over it (Eq. 16), in the order of osb::dilatationSum.
template <bool Unit, class Extension>
PF_INLINE double updatePlasticExtension(const double* __restrict w, const double* __restrict xr,
                                        const double* __restrict len, const double* __restrict vj, int n,
                                        bool inBlock, double* __restrict ep, const Extension& extension) {
  osb::Lanes acc = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) {
    const osb::Lanes x = c.load(xr + k);
    const osb::Lanes e = extension(k, c);
    c.store(ep + k, e);
    acc += osb::weighted<Unit>(c, w, k, x) * ((c.load(len + k) - x) - e) * c.load(vj + k);
  });
  return osb::laneSum(acc);
}

// sum e^dp_n+1 e^dp_n V: negative when the flow carried the plastic extension through zero (against its direction).
PF_INLINE double alongCommitted(const double* __restrict ep, const double* __restrict epN,
                                const double* __restrict vj, int n, bool inBlock) {
  osb::Lanes along = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) { along += c.load(ep + k) * c.load(epN + k) * c.load(vj + k); });
  return osb::laneSum(along);
}

// Force from the updated state, written as osbElasticForce writes it (t = t^iso + t^d, Eqs. 7-13
// with e^d - e^dp), along the deformed bond. B: c.B, times Peridigm's shear correction factor if on -- it
// scales the whole deviatoric state, its -c theta x part included (elastic_plastic_hardening.cxx).
template <bool Unit>
PF_INLINE void addJ2BondForces(const FamilyView& fam, const OsbConstants& c, int i, const osb::FamilyScratch& scr,
                               bool inBlock, const double* __restrict w, const double* __restrict xr,
                               const double* __restrict ep, double theta, double invm, double B,
                               osb::Quad* force) {
  const double* __restrict len = scr.len;
  const double iso = (c.A - B * c.c) * theta * invm;
  const double dev = B * invm;
  auto forceOverLength = [&](int k, auto ch) {  // s = t / |y_j - y_i|; e^dp = 0 gives the elastic s
    const osb::Lanes x = ch.load(xr + k), l = ch.load(len + k, 1.0);
    return osb::weighted<Unit>(ch, w, k, iso * x + dev * ((l - x) - ch.load(ep + k))) / l;
  };
  osb::addBondForces(fam, i, scr, inBlock, forceOverLength, force);
}

OsbJ2NodeState committedState(const J2Fields& s, int i) { return {s.lambdaN[i], s.alphaN[i], s.qN[i], s.signN[i]}; }

// volume: V_i, for the plastic work sigma_vm |d eps_p| V_i (Eqs. 20, 55), the model's sigma : d eps^p on the paths
// where it equals classical J2 (the flow is along t^d), backward Euler as the return.
void storeNodeState(const J2Fields& s, int i, const OsbJ2Return& r, double theta, double volume) {
  s.lambda[i] = r.state.lambda;
  s.alpha[i] = r.state.alpha;
  s.q[i] = r.state.q;
  s.sign[i] = r.state.sign;
  s.vonMises[i] = r.vonMises;
  s.signedVonMises[i] = r.state.sign * r.vonMises;
  s.theta[i] = theta;
  if (s.iterations) s.iterations[i] = r.iterations;
  if (s.dissipated) s.dissipated[i] = s.dissipatedN[i] + r.vonMises * r.plasticStrain * volume;
}

// Node i from its gathered family: trial state, return mapping, plastic extension, node state, force.
template <bool Unit>
PF_INLINE void j2Node(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const J2Fields& s, int i,
                      const osb::FamilyScratch& scr, osb::Quad* force) {
  const OsbConstants& c = p.osb;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const double* __restrict xr = fam.refLength + b0;
  const double* __restrict w = fam.influence + b0;
  const double* __restrict epN = s.edpN + b0;
  double* __restrict ep = s.edp + b0;
  const double* __restrict len = scr.len;
  const double* __restrict vj = scr.vj;
  double* __restrict tdv = scr.a;  // trial deviatoric force state
  const bool inBlock = osb::chunksStayInBlock(fam, i);
  const double m = fam.weightedVolume[i];
  const double invm = 1.0 / m;
  const J2NodeTrial tr = j2NodeTrial<Unit>(fam, p, flow, s.scf, epN, i, scr, tdv);
  const OsbJ2Constants& k = tr.k;
  const double B = tr.B, thetaTr = tr.thetaTr;
  const OsbTrialMoments& trial = tr.moments;

  OsbJ2Return r = returnMapping(trial, committedState(s, i), k);  // osbJ2ReturnMapping, inlined
  if (r.status != OsbJ2Status::Ok) throwReturnFailure(r, s.qN[i], p.maxIterations, i);

  // Plastic extension (Eqs. 52, 58) and the dilatation it implies.
  double theta = thetaTr;
  if (r.dlambda > 0.0) {
    const double a1 = r.dlambda * r.G1, a2 = r.dlambda * flow.phi * r.G2 * r.pp;
    const bool overOmega = !Unit && flow.flowOverOmega, omegaSplit = !Unit && k.omegaSplit;
    // Eqs. 52, 58: e^dp_n + a1 (t^d - pp x) + a2 x, the returned t_perp and pp x scaled by dlambda and phi; or, for a
    // non-unit influence in 3D and plane strain (J2Flow::flowOverOmega), e^dp_n + a1 u with u = t^d_tr / omega
    // (trialExtensionFlow), so that omega bm (e - c theta x - e^dp_n+1) = G1 t^d_tr, the returned state; in plane
    // stress (OsbJ2Constants::omegaSplit, pp along omega x) e^dp_n + a1 u + (a2 - a1 pp) x (OsbJ2OmegaSplit.hpp).
    const double pp = r.pp, bm = k.bm, cth = c.c * thetaTr, ax = a2 - a1 * pp;
    const double sum =
        omegaSplit ? updatePlasticExtension<Unit>(w, xr, len, vj, n, inBlock, ep, [&](int b, auto ch) {
                       return ch.load(epN + b) + a1 * trialExtensionFlow(ch, xr, len, epN, bm, cth, b) +
                              ax * ch.load(xr + b);
                     })
        : overOmega ? updatePlasticExtension<Unit>(w, xr, len, vj, n, inBlock, ep, [&](int b, auto ch) {
                        return ch.load(epN + b) + a1 * trialExtensionFlow(ch, xr, len, epN, bm, cth, b);
                      })
                    : updatePlasticExtension<Unit>(w, xr, len, vj, n, inBlock, ep, [&](int b, auto ch) {
                        const osb::Lanes x = ch.load(xr + b);
                        return ch.load(epN + b) + a1 * (ch.load(tdv + b) - pp * x) + a2 * x;
                      });
    // Plane strain: theta from the total extension, i.e. the trial one (see J2Flow::beta).
    if (flow.beta) theta = c.k * c.D * sum / m;
    // q is measured along e^dp: when the flow carried e^dp through zero, its direction, and so q's sign, turned. With
    // Eq. 52's flow (G1 = G2, phi = 1 where this sign is used) sum e^dp_n+1 e^dp_n V = |e^dp_n|^2 + a1 Se, which
    // can only turn negative when Se < 0, so the sum is formed only then (and for the omega-free flow).
    if (k.signRule == OsbJ2SignRule::PlasticExtension && (trial.Se < 0.0 || overOmega) &&
        alongCommitted(ep, epN, vj, n, inBlock) < 0.0)
      r.state.q = -r.state.q;
  } else {
    for (int b = 0; b < n; ++b) ep[b] = epN[b];  // every trial value is written: StateStore::commit swaps
  }
  storeNodeState(s, i, r, theta, fam.volume[i]);
  addJ2BondForces<Unit>(fam, c, i, scr, inBlock, w, xr, ep, theta, invm, B, force);
}

}  // namespace

}  // namespace pf
