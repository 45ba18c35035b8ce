#pragma once
// Critical-stretch bond breaking (Peridigm's "Critical Stretch" damage model), as every kernel applies it:
// a bond is broken (trial) if it was broken at the last committed step or its stretch
// (|y_j - y_i| - |xi|) / |xi| exceeds FamilyView::criticalStretch now. Broken bonds never heal. The OSB
// kernels apply bondBroken in their gather (OsbBondLoops.hpp), scalar loops breakBond.
//
// Contract of the per-bond flags (both copies valid for every bond at all times) without streaming them at
// every evaluation: bonds never heal, so a node with no broken bond committed (brokenCountN = 0) had none at
// the step before either, and the trial copy StateStore::commit swaps in (that step's flags) is all 0 for it
// unless an earlier evaluation of the same step broke some (then its trial count is not 0). A kernel
// therefore writes a node's trial flags only when the node has broken bonds now or had in its last trial.
#include "BondFamily.hpp"

namespace pf {

// The rule for one bond: broken before (committed flag bn != 0) or stretched past s_c now. The stretch test
// is len - |xi| > s_c |xi| (no division: the kernels apply it to every bond at every evaluation); it differs
// from Peridigm's quotient (len - |xi|)/|xi| > s_c only for a stretch equal to s_c to within round-off.
inline bool bondBroken(double bn, double len, double xi, double sc) { return (bn != 0.0) | (len - xi > sc * xi); }

// The same rule for one bond b of length len, for scalar loops: writes its trial flag, returns whether broken.
// The caller sets the node's Damage and trial count (finishNode).
inline bool breakBond(const FamilyView& fam, int b, double len) {
  const bool broken = bondBroken(fam.brokenN[b], len, fam.refLength[b], fam.criticalStretch);
  fam.broken[b] = broken ? 1.0 : 0.0;
  return broken;
}

// After a scalar loop over node i's n bonds with `broken` of them broken: its trial count and Damage.
inline void finishNode(const FamilyView& fam, int i, int n, double broken) {
  fam.brokenCount[i] = broken;
  fam.damage[i] = n > 0 ? broken / n : 0.0;
}

}  // namespace pf
