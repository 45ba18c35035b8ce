// Thermal expansion in the OSB J2 solid (osbJ2ThermalForce, OsbPlasticKernels.hpp): the J2 kernel's node update
// (OsbJ2Node.hpp) over the thermal gather (OsbThermalGather.hpp), and plane strain's volume term. A kernel source
// of its own, so that the mechanics-only kernel (OsbPlasticKernels.cpp) compiles exactly as before.
#include "OsbJ2Node.hpp"
#include "OsbPlasticKernels.hpp"
#include "OsbThermalGather.hpp"

namespace pf {

namespace {

// Plane strain: the dilatation's thermal part theta_th = volumeStrain sum omega |xi|^2 V_j / m over the bonds
// present (3 alpha dT for a whole family), taken out of the isotropic force only: t_th = -A theta_th omega |xi| / m
// along each bond (j2Node's force used the total theta both for A and for the deviatoric c theta), and out of node
// i's Dilatation output.
template <bool Unit>
PF_INLINE void addThermalVolumeForce(const FamilyView& fam, const OsbConstants& c, int i, double volumeStrain,
                                     const osb::FamilyScratch& scr, double* theta, osb::Quad* force) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const double m = fam.weightedVolume[i];
  if (n == 0 || !(m > 0.0)) return;
  const double* __restrict xr = fam.refLength + b0;
  const double* __restrict w = fam.influence + b0;
  double sum = 0.0;
  for (int b = 0; b < n; ++b) sum += (Unit ? 1.0 : w[b]) * xr[b] * xr[b] * scr.vj[b];
  const double thetaTh = volumeStrain * sum / m;
  theta[i] -= thetaTh;
  const double iso = -c.A * thetaTh / m;
  auto forceOverLength = [&](int k, auto ch) {
    const osb::Lanes x = ch.load(xr + k), l = ch.load(scr.len + k, 1.0);
    return osb::weighted<Unit>(ch, w, k, iso * x) / l;
  };
  osb::addBondForces(fam, i, scr, osb::chunksStayInBlock(fam, i), forceOverLength, force);
}

// j2Force's loop (OsbPlasticKernels.cpp) over the thermal gather; no software prefetch (not tuned).
template <bool Unit>
PF_INLINE void j2ThermalForce(const FamilyView& fam, const J2Parameters& p, const J2Thermal& th, const double* dT,
                              const double* y, const J2Fields& s, double* force) {
  const J2Flow flow = j2Flow(p);
  osb::FamilyScratch& scr = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, force);
  FamilyView noDamage = fam;
  noDamage.brokenN = nullptr;
  for (int i = fam.begin; i < fam.end; ++i) {
    osb::gatherThermalFamily(fam, noDamage, rec.pos, i, th.breaking * dT[i], th.extension * dT[i], scr);
    j2Node<Unit>(fam, p, flow, s, i, scr, rec.force);
    if (th.volume != 0.0) addThermalVolumeForce<Unit>(fam, p.osb, i, th.volume * dT[i], scr, s.theta, rec.force);
  }
  osb::storeForces(fam, rec, force);
}

}  // namespace

PF_KERNEL_CLONES void osbJ2ThermalForce(const FamilyView& fam, const J2Parameters& p, const J2Thermal& th,
                                        const double* dT, const double* y, const J2Fields& s, double* force) {
  if (fam.unitInfluence) j2ThermalForce<true>(fam, p, th, dT, y, s, force);
  else j2ThermalForce<false>(fam, p, th, dT, y, s, force);
}

}  // namespace pf
