#pragma once
// The gather of a thermally expanding family, for the thermal J2 kernel (OsbPlasticKernels.cpp,
// osbJ2ThermalForce): osb::gatherFamily without its damage test, then the critical-stretch test on the length
// less the free thermal extension breakStrain |xi|, then each bond's length less its free thermal extension
// strain |xi| with y_j - y_i scaled to keep its direction. Every later loop, written with e = len - |xi| and the
// direction (y_j - y_i) / len, then sees the mechanical extension; the mechanics-only gather and kernels are
// untouched. Internal to materials/.
#include "OsbBondLoops.hpp"

namespace pf {
namespace osb {

// noDamage: fam with brokenN null (gatherFamily then tests nothing); breakStrain, strain: a dT_i of the node.
// Uses sc.a for the tested lengths (free until the caller's own loops). Returns the family's size.
PF_INLINE int gatherThermalFamily(const FamilyView& fam, const FamilyView& noDamage, const Quad* __restrict pos, int i,
                                  double breakStrain, double strain, FamilyScratch& sc) {
  const int b0 = fam.offsets[i];
  const int n = gatherFamily(noDamage, pos, i, sc);
  const double* __restrict xr = fam.refLength + b0;
  if (fam.brokenN) {
    // gatherFamily's damage block, on the mechanical lengths (core/BondDamage.hpp's contract).
    double* __restrict tested = sc.a;
    for (int b = 0; b < n; ++b) tested[b] = sc.len[b] - breakStrain * xr[b];
    long count = 0;
    const bool intact = fam.brokenCountN[i] == 0.0;
    if (intact) count = countStretched(n, xr, tested, fam.criticalStretch);
    if (count > 0 || !intact)
      count = dropBrokenBonds(n, xr, fam.brokenN + b0, fam.broken + b0, fam.criticalStretch, tested, sc.vj, sc.d0,
                              sc.d1, sc.d2);
    else if (fam.brokenCount[i] != 0.0)
      for (int b = 0; b < n; ++b) fam.broken[b0 + b] = 0.0;
    fam.brokenCount[i] = static_cast<double>(count);
    fam.damage[i] = n > 0 ? static_cast<double>(count) / n : 0.0;
  }
  if (strain != 0.0)
    for (int b = 0; b < n; ++b) {
      const double l = sc.len[b] - strain * xr[b], r = l / sc.len[b];
      sc.d0[b] *= r;
      sc.d1[b] *= r;
      sc.d2[b] *= r;
      sc.len[b] = l;
    }
  return n;
}

}  // namespace osb
}  // namespace pf
