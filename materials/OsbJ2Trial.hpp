#pragma once
// The trial part of the OSB J2 node update (Pirzadeh et al. 2024 §3.2, Eqs. 16, 40-41): the flow constants
// of the dimension and the trial dilatation and deviatoric state of one gathered family. Shared by the force
// kernel (OsbPlasticKernels.cpp) and its consistent tangent (OsbPlasticTangent.cpp) so that both see the same
// bits and so take the same elastic/plastic branch. Internal to materials/.
#include "J2ReturnMapping.hpp"
#include "OsbBondLoops.hpp"
#include "OsbJ2OmegaSplit.hpp"
#include "OsbPlasticKernels.hpp"

namespace pf {

// How the flow treats the x-component of t^d in this dimension, and the material part of the
// return-mapping constants (the node part, yield and bm, is set per node).
struct J2Flow {
  // beta: does the dilatation see the plastic extension (Eq. 16)? 3D: either way (sum x e^dp = 0 for
  // omega = 1). Plane stress: yes. Plane strain: no -- only then is the in-plane mean stress classical
  // (see docs/materials.md).
  bool beta;
  // phi: weight of the x-component (t.x) x/m of the flow direction. 1 = Eq. 52 (3D, plane strain);
  // plane stress needs 2 to follow the 3D J2 flow with sigma_zz = 0 (sigma_zz-free eps_p_zz).
  double phi;
  // For a non-unit influence function in 3D and plane strain the plastic extension flows along t^d_tr / omega (the
  // trial deviatoric extension, trialExtensionFlow) instead of t^d_tr (Eq. 52): then the stored state is the returned
  // one, G t^d_tr, on the yield surface. The same as Eq. 52 where omega = 1; the kernels read it only for omega != 1.
  bool flowOverOmega;
  // Plane stress with a non-unit influence function: the return splits t^d_tr along omega x and the plastic extension
  // flows along t_perp / omega + phi pp x (OsbJ2OmegaSplit.hpp), which closes with the omega-weighted theta feedback.
  // The kernels read it only for omega != 1 (OsbJ2Constants::omegaSplit is set per node).
  bool omegaSplit;
  OsbJ2Constants ret;
};

J2Flow j2Flow(const J2Parameters& p);

// The weighted volume the yield-surface constants are written with (YieldNormalization).
double yieldVolume(const FamilyView& fam, const J2Parameters& p, double m);

// Writes the trial deviatoric force state t^d_tr = omega bm (e - c theta_tr x - e^dp_n) (Eqs. 40-41) to
// tdv and returns its moments but x.x, bond k in partial sum k mod kLanes.
template <bool Unit>
PF_INLINE OsbTrialMoments trialDeviatoricState(const double* __restrict w, const double* __restrict xr,
                                               const double* __restrict len, const double* __restrict epN,
                                               const double* __restrict vj, double bm, double cth, int n,
                                               bool inBlock, double* __restrict tdv) {
  osb::Lanes S2 = {}, Sx = {}, S3 = {}, A3 = {}, Se = {};
  osb::forEachChunk(n, inBlock, [&](int k, auto c) {
    const osb::Lanes x = c.load(xr + k), v = c.load(vj + k), e = c.load(epN + k);
    const osb::Lanes bmv = osb::Lanes{} + bm;
    const osb::Lanes td = osb::weighted<Unit>(c, w, k, bmv) * (((c.load(len + k) - x) - cth * x) - e);
    const osb::Lanes tv = td * v;
    osb::FullChunk{}.store(tdv + k, td);  // scratch: padded to whole chunks
    S2 += td * tv; Sx += x * tv; S3 += td * td * tv; A3 += osb::absLanes(td) * td * tv; Se += e * tv;
  });
  return {osb::laneSum(S2), osb::laneSum(Sx), osb::laneSum(S3), osb::laneSum(A3), 0.0, osb::laneSum(Se)};
}

// t^d_tr / omega at the chunk of bond k: bm ((|Y| - x) - c theta_tr x - e^dp_n), cth = c theta_tr (J2Flow::flowOverOmega).
template <class Chunk>
PF_INLINE osb::Lanes trialExtensionFlow(const Chunk& c, const double* __restrict xr, const double* __restrict len,
                                        const double* __restrict epN, double bm, double cth, int k) {
  const osb::Lanes x = c.load(xr + k);
  return bm * (((c.load(len + k) - x) - cth * x) - c.load(epN + k));
}

// Node i's trial state from its gathered family (scr) and committed plastic extension epN (the family's
// first bond): the return-mapping constants of the node, B (c.B times Peridigm's shear correction factor
// scf_i if scf is not null), the trial dilatation and the trial moments; t^d_tr goes to tdv.
struct J2NodeTrial {
  OsbJ2Constants k;
  double B, thetaTr;
  OsbTrialMoments moments;
};

template <bool Unit>
PF_INLINE J2NodeTrial j2NodeTrial(const FamilyView& fam, const J2Parameters& p, const J2Flow& flow, const double* scf,
                                  const double* __restrict epN, int i, const osb::FamilyScratch& scr,
                                  double* __restrict tdv) {
  const OsbConstants& c = p.osb;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const double* __restrict xr = fam.refLength + b0;
  const double* __restrict w = fam.influence + b0;
  const bool inBlock = osb::chunksStayInBlock(fam, i);
  const double m = fam.weightedVolume[i];
  J2NodeTrial t;
  t.k = flow.ret;
  t.k.yield = osbYieldConstants(p.dim, yieldVolume(fam, p, m));
  // Peridigm's correction: deviatoric modulus times s, yield value times s^2 (exact no-ops when off).
  t.B = scf ? c.B * scf[i] : c.B;
  t.k.bm = t.B * (1.0 / m);  // -B of Eq. 48 (B here is 15 mu or 8 mu)
  if (scf) t.k.yield.Cy *= scf[i] * scf[i];
  // Trial dilatation from the committed plastic extension (Eqs. 4/16); same operations as
  // osbDilatation so that the elastic response is bit-identical to "Elastic".
  // x.x (Eq. 41) comes out of the same pass.
  double Xx = 0.0;
  const double trialSum = osb::dilatationSum<Unit>(w, xr, scr.len, flow.beta ? epN : nullptr, scr.vj, n, inBlock, &Xx);
  t.thetaTr = c.k * c.D * trialSum / m;
  t.moments = trialDeviatoricState<Unit>(w, xr, scr.len, epN, scr.vj, t.k.bm, c.c * t.thetaTr, n, inBlock, tdv);
  t.moments.Xx = Xx;
  t.k.omegaSplit = !Unit && flow.omegaSplit;
  if (t.k.omegaSplit) omegaSplitMoments<Unit>(w, xr, scr.vj, tdv, n, inBlock, m, t.moments);
  return t;
}

}  // namespace pf
