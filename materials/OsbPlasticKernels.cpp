#include "OsbPlasticKernels.hpp"

#include "OsbJ2Node.hpp"
#include "OsbGradientCorrection.hpp"

namespace pf {

OsbJ2Return osbJ2ReturnMapping(const OsbTrialMoments& trial, const OsbJ2NodeState& committed,
                               const OsbJ2Constants& k) {
  return returnMapping(trial, committed, k);
}

// ---- The bond loop: gather, trial moments, return mapping, plastic extension, force ----

J2Flow j2Flow(const J2Parameters& p) {
  const OsbConstants& c = p.osb;
  J2Flow f;
  f.beta = p.dim != Dimension::PlaneStrain;
  f.phi = p.dim == Dimension::PlaneStress ? 2.0 : 1.0;
  // G1 = G2 and phi = 1 there, so Eq. 52's flow is dlambda G1 t^d_tr and its omega-free twin closes exactly; plane
  // stress's theta feedback (beta, phi = 2) closes only with the split along omega x (docs/materials.md, limitation iii).
  f.flowOverOmega = p.dim != Dimension::PlaneStress;
  f.omegaSplit = p.dim == Dimension::PlaneStress;
  f.ret = OsbJ2Constants{};
  // Decay rate of the x-component relative to the rest during the return (G2 vs G1 of Eq. 47):
  // the flow changes theta when beta is set, which feeds back through -c theta x.
  f.ret.g2 = f.phi * (1.0 - (f.beta ? c.c * c.k * c.D : 0.0));
  f.ret.yieldStress = p.yieldStress;
  f.ret.isoHardening = p.isoHardening;
  f.ret.kinHardening = p.kinHardening;
  f.ret.peridigmLaw = p.peridigmLaw;
  f.ret.peridigmH = p.peridigmHardening;
  f.ret.tolerance = p.tolerance;
  f.ret.maxIterations = p.maxIterations;
  // 3D and plane strain measure q along the plastic extension; plane stress keeps the paper's third-moment sign, which
  // fits its cyclic uniaxial paths better (docs/materials.md), taken from the committed state once a node has a back
  // stress (OsbJ2SignRule).
  f.ret.signRule =
      p.dim == Dimension::PlaneStress ? OsbJ2SignRule::CommittedThirdMoment : OsbJ2SignRule::PlasticExtension;
  return f;
}

double yieldVolume(const FamilyView& fam, const J2Parameters& p, double m) {
  constexpr double kPi = 3.14159265358979323846;
  if (p.norm != YieldNormalization::Continuum) return m;
  const double d = fam.horizon;
  return p.dim == Dimension::ThreeD ? 0.8 * kPi * d * d * d * d * d : 0.5 * kPi * p.thickness * d * d * d * d;
}

namespace {

// The kernel for one influence kind; Unit: omega = 1 everywhere, the array is not read.
template <bool Unit>
PF_INLINE void j2Force(const FamilyView& fam, const J2Parameters& p, const double* y, const J2Fields& s,
                       double* force) {
  const J2Flow flow = j2Flow(p);
  osb::FamilyScratch& scr = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, force);
  const bool prefetchRecords = osb::prefetchRecordsPays(fam, rec);
  const bool planar = p.dim != Dimension::ThreeD;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int ahead = osb::prefetchFamily(fam, i);
    if (ahead >= 0) {
      osb::prefetchBondRange(fam, ahead, s.edpN, false);
      osb::prefetchBondRange(fam, ahead, s.edp, true);
    }
    if (prefetchRecords) osb::prefetchNeighbourRecords(fam, rec, i);
    // Bond vectors, lengths (one sqrt per bond and step) and neighbour volumes, once per node.
    osb::gatherFamily(fam, rec.pos, i, scr);
    if (p.gradientCorrection) osb::removeQuadratic<Unit>(fam, i, planar, scr);
    j2Node<Unit>(fam, p, flow, s, i, scr, rec.force);
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
