#include "OsbPlasticKernels.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Material.hpp"
#include "OsbBondLoops.hpp"

namespace pf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Constants of the yield surface written with the weighted volume my (see YieldNormalization).
// psi0 = Cy sigma_bar^2 (Eqs. 39/46), |d eps_p| = dlambda sqrt(Ce psi) (Eq. 55 with the 2D term),
// psi = |t|^2/2 + a2 (t.x)^2 (Eq. 31).
struct YieldConstants {
  double Cy, Ce, a2;
};

YieldConstants yieldConstants(Dimension dim, double my) {
  if (dim == Dimension::ThreeD) return {2.5 / my, 10.0 / my, 0.0};
  // 2D: psi0 = 8 sigma^2/(3 pi h delta^4) = 4 sigma^2/(3 m) as printed. The (t.x)^2 coefficient that
  // reproduces 3D J2 in plane strain and plane stress with c = 5/12 resp. 1/3 + kappa/(8 mu) is
  // 5/(2m), not the printed 4/(pi h delta^4) = 2/m; Ce follows from |de_p|^2 = dlambda^2 8 psi/m.
  return {4.0 / (3.0 * my), 16.0 / (3.0 * my), 2.5 / my};
}

// Moments of the trial deviatoric force state over the family (Eqs. 31, 40-41): |t|^2, t.x, and the
// third moment and its absolute value (sign of sigma_vm); x.x comes from osb::dilatationSum.
struct TrialMoments {
  double S2, Sx, S3, A3;
};

// Writes the trial deviatoric force state t^d_tr = omega bm (e - c theta_tr x - e^dp_n) (Eqs. 40-41) to
// tdv and returns its moments, bond k in partial sum k mod kLanes.
template <bool Unit>
PF_INLINE TrialMoments trialDeviatoricState(const double* __restrict w, const double* __restrict xr,
                                            const double* __restrict len, const double* __restrict epN,
                                            const double* __restrict vj, double bm, double cth, int n,
                                            bool inBlock, double* __restrict tdv) {
  osb::Lanes S2 = {}, Sx = {}, S3 = {}, A3 = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) {
    const osb::Lanes x = c.load(xr + k), v = c.load(vj + k);
    const osb::Lanes bmv = osb::Lanes{} + bm;
    const osb::Lanes td = osb::weighted<Unit>(c, w, k, bmv) * (((c.load(len + k) - x) - cth * x) - c.load(epN + k));
    const osb::Lanes tv = td * v;
    osb::FullChunk{}.store(tdv + k, td);  // scratch: padded to whole chunks
    S2 += td * tv; Sx += x * tv; S3 += td * td * tv; A3 += osb::absLanes(td) * td * tv;
  });
  return {osb::laneSum(S2), osb::laneSum(Sx), osb::laneSum(S3), osb::laneSum(A3)};
}

// e^dp_n+1 = e^dp_n + a1 (t^d - pp x) + a2 x (Eqs. 52, 58: the returned t_perp and pp x scaled by
// dlambda and phi), written to ep; returns the dilatation sum over the new e^dp (Eq. 16), in the order
// of osb::dilatationSum.
template <bool Unit>
PF_INLINE double updatePlasticExtension(const double* __restrict w, const double* __restrict xr,
                                        const double* __restrict len, const double* __restrict epN,
                                        const double* __restrict vj, const double* __restrict tdv, double a1,
                                        double a2, double pp, int n, bool inBlock,
                                        double* __restrict ep) {
  osb::Lanes acc = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) {
    const osb::Lanes x = c.load(xr + k);
    const osb::Lanes e = c.load(epN + k) + a1 * (c.load(tdv + k) - pp * x) + a2 * x;
    c.store(ep + k, e);
    acc += osb::weighted<Unit>(c, w, k, x) * ((c.load(len + k) - x) - e) * c.load(vj + k);
  });
  return osb::laneSum(acc);
}

// The kernel for one influence kind; Unit: omega = 1 everywhere, the array is not read.
template <bool Unit>
PF_INLINE void j2Force(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s,
                       double* force) {
  const OsbConstants& c = p.osb;
  // beta: does the dilatation see the plastic extension (Eq. 16)? 3D: either way (sum x e^dp = 0 for
  // omega = 1). Plane stress: yes. Plane strain: no -- only then is the in-plane mean stress classical
  // (see docs/materials.md).
  const bool beta = p.dim != Dimension::PlaneStrain;
  // phi: weight of the x-component (t.x) x/m of the flow direction. 1 = Eq. 52 (3D, plane strain);
  // plane stress needs 2 to follow the 3D J2 flow with sigma_zz = 0 (sigma_zz-free eps_p_zz).
  const double phi = p.dim == Dimension::PlaneStress ? 2.0 : 1.0;
  // Decay rate of the x-component relative to the rest during the return (G2 vs G1 of Eq. 47):
  // the flow changes theta when beta is set, which feeds back through -c theta x.
  const double g2 = phi * (1.0 - (beta ? c.c * c.k * c.D : 0.0));
  const double KH = p.isoHardening + p.kinHardening;

  osb::FamilyScratch& scr = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, force);
  const double* __restrict len = scr.len;
  const double* __restrict vj = scr.vj;
  double* __restrict tdv = scr.a;  // trial deviatoric force state
  const bool prefetchRecords = osb::prefetchRecordsPays(fam, rec);

  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
    const double* __restrict xr = fam.refLength + b0;
    const double* __restrict w = fam.influence + b0;
    const double* __restrict epN = s.edpN + b0;
    double* __restrict ep = s.edp + b0;
    const bool inBlock = osb::chunksStayInBlock(fam, i);
    const int ahead = osb::prefetchFamily(fam, i);
    if (ahead >= 0) {
      osb::prefetchBondRange(fam, ahead, s.edpN, false);
      osb::prefetchBondRange(fam, ahead, s.edp, true);
    }
    if (prefetchRecords) osb::prefetchNeighbourRecords(fam, rec, i);
    const double m = fam.weightedVolume[i];
    const double invm = 1.0 / m;
    double my = m;
    if (p.norm == YieldNormalization::Continuum) {
      const double d = fam.horizon;
      my = p.dim == Dimension::ThreeD ? 0.8 * kPi * d * d * d * d * d : 0.5 * kPi * p.thickness * d * d * d * d;
    }
    const YieldConstants yc = yieldConstants(p.dim, my);
    const double bm = c.B * invm;  // -B of Eq. 48 (B here is 15 mu or 8 mu)

    // Bond vectors, lengths (one sqrt per bond and step) and neighbour volumes, once per node.
    osb::gatherFamily(fam, rec.pos, i, scr);

    // Trial dilatation from the committed plastic extension (Eqs. 4/16); same operations as
    // osbDilatation so that the elastic response is bit-identical to "Elastic".
    // x.x (Eq. 41) comes out of the same pass.
    double Xx = 0.0;
    double sum = osb::dilatationSum<Unit>(w, xr, len, beta ? epN : nullptr, vj, n, inBlock, &Xx);
    const double thetaTr = c.k * c.D * sum / m;

    // Trial deviatoric force state (Eqs. 40-41) and its moments.
    const double cth = c.c * thetaTr;
    const TrialMoments mo = trialDeviatoricState<Unit>(w, xr, len, epN, vj, bm, cth, n, inBlock, tdv);
    const double S2 = mo.S2, Sx = mo.Sx, S3 = mo.S3, A3 = mo.A3;
    // Split t^d = t_perp + pp x with t_perp . x = 0: the two parts decay at different rates in plane
    // stress, and only pp enters the 2D (t.x)^2 term.
    const double pp = Sx / Xx;
    const double Pperp = std::max(S2 - pp * pp * Xx, 0.0);  // std::fmax is a libm call
    const double Ppar = pp * pp * Xx * (1.0 + 2.0 * yc.a2 * Xx);
    const double psiTr = 0.5 * (Pperp + Ppar);
    const double vmTr = std::sqrt(psiTr / yc.Cy);  // Eq. 20 (3D with /2, see design doc), 2D analogue

    // Sign of sigma_vm: third moment of t^d (analogue of J3); kept from the last step when it vanishes
    // (pure shear), +1 for a virgin point.
    double sgn = s.signN[i] != 0.0 ? s.signN[i] : 1.0;
    if (S3 > 1e-8 * std::fabs(A3)) sgn = 1.0;
    else if (S3 < -1e-8 * std::fabs(A3)) sgn = -1.0;
    // Direction of plastic flow along the loading axis, sign(sigma_vm - q) of Eqs. 45-46, 56.
    const double dir = sgn * vmTr - s.qN[i] >= 0.0 ? 1.0 : -1.0;
    // Current yield level, Eqs. 39/46 (not Eq. 32, which drops q after the sign).
    const double sbarN = p.yieldStress + p.isoHardening * s.alphaN[i] + dir * s.qN[i];
    if (!(sbarN > 0.0)) {
      std::ostringstream msg;
      msg << "J2 return mapping: back stress " << s.qN[i] << " exceeds the yield level at node " << i
          << "; the scalar kinematic hardening model does not cover this state";
      throw ConstitutiveFailure(msg.str());
    }

    double dlam = 0.0, G1 = 1.0, G2 = 1.0, vm = vmTr, deps = 0.0;
    int iters = 0;
    if (vmTr > sbarN) {  // f(t^d_trial) > 0, Eq. 31
      // Initial guess: exact when G1 = G2 (3D, plane strain), where the return is radial with slope
      // bm/(2 Cy) (= 3 mu for the discrete normalisation).
      const double e0 = (vmTr - sbarN) / (bm / (2.0 * yc.Cy) + KH);
      dlam = e0 / (2.0 * yc.Cy * (sbarN + KH * e0));
      // Newton on Eq. 50 written as sqrt(psi/Cy) = sigma_bar (same root, better scaled), with
      // alpha and q following Eqs. 55-57 so sigma_bar = sigma_bar_n + (K + H) |d eps_p|.
      bool converged = false;
      for (;;) {
        G1 = 1.0 / (1.0 + bm * dlam);
        G2 = 1.0 / (1.0 + g2 * bm * dlam);
        const double psi = 0.5 * (G1 * G1 * Pperp + G2 * G2 * Ppar);
        const double dpsi = -bm * (G1 * G1 * G1 * Pperp + g2 * G2 * G2 * G2 * Ppar);
        const double root = std::sqrt(yc.Ce * psi);
        vm = std::sqrt(psi / yc.Cy);
        deps = dlam * root;
        const double F = vm - sbarN - KH * deps;
        if (std::fabs(F) <= p.tolerance * vmTr) { converged = true; break; }
        if (iters == p.maxIterations) break;
        const double dF = dpsi / (2.0 * std::sqrt(yc.Cy * psi)) - KH * (root + dlam * yc.Ce * dpsi / (2.0 * root));
        dlam -= F / dF;
        if (dlam < 0.0) dlam = 0.0;
        ++iters;
      }
      if (!converged) {
        std::ostringstream msg;
        msg << "J2 return mapping did not converge in " << p.maxIterations << " iterations at node " << i
            << " (trial von Mises " << vmTr << ", yield level " << sbarN << ")";
        throw ConstitutiveFailure(msg.str());
      }
    }

    // Plastic extension (Eqs. 52, 58) and the dilatation it implies.
    double theta = thetaTr;
    if (dlam > 0.0) {
      const double a1 = dlam * G1, a2 = dlam * phi * G2 * pp;
      sum = updatePlasticExtension<Unit>(w, xr, len, epN, vj, tdv, a1, a2, pp, n, inBlock, ep);
      // Plane strain: theta from the total extension, i.e. the trial one (see beta above).
      if (beta) theta = c.k * c.D * sum / m;
    } else {
      for (int k = 0; k < n; ++k) ep[k] = epN[k];  // every trial value is written: StateStore::commit swaps
    }

    s.lambda[i] = s.lambdaN[i] + dlam;
    s.alpha[i] = s.alphaN[i] + deps;                       // Eq. 57
    s.q[i] = s.qN[i] + dir * p.kinHardening * deps;       // Eq. 56
    s.sign[i] = sgn;
    s.vonMises[i] = vm;
    s.signedVonMises[i] = sgn * vm;
    s.theta[i] = theta;
    if (s.iterations) s.iterations[i] = iters;

    // Force from the updated state, written as osbElasticForce writes it (t = t^iso + t^d, Eqs. 7-13
    // with e^d - e^dp), along the deformed bond.
    const double iso = (c.A - c.B * c.c) * theta * invm;
    const double dev = c.B * invm;
    auto forceOverLength = [&](int k, auto ch) {  // s = t / |y_j - y_i|; e^dp = 0 gives the elastic s
      const osb::Lanes x = ch.load(xr + k), l = ch.load(len + k, 1.0);
      return osb::weighted<Unit>(ch, w, k, iso * x + dev * ((l - x) - ch.load(ep + k))) / l;
    };
    osb::addBondForces(fam, i, scr, inBlock, forceOverLength, rec.force);
  }
  osb::storeForces(fam, rec, force);
}

}  // namespace

PF_KERNEL_CLONES void osbJ2Force(const FamilyView& fam, const J2Parameters& p, const double* y,
                                 const J2Fields& s, double* force) {
  if (fam.unitInfluence) j2Force<true>(fam, p, y, s, force);
  else j2Force<false>(fam, p, y, s, force);
}

}  // namespace pf
