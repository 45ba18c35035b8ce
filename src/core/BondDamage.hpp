#pragma once
// Critical-stretch bond breaking (Peridigm's "Critical Stretch" damage model), as every kernel applies it:
// a bond is broken (trial) if it was broken at the last committed step or its stretch
// (|y_j - y_i| - |xi|) / |xi| exceeds FamilyView::criticalStretch now. Broken bonds never heal.
#include "BondFamily.hpp"

namespace pf {

// Node i's bonds given their deformed lengths len[k] (k = 0 .. n-1, bond offsets[i] + k): writes the trial
// flags and the node's Damage, and returns keep[k] = 0 for a broken bond, 1 for an intact one. Only for
// fam.brokenN != null. The stretch is computed as Peridigm computes it (a quotient), so a bond at the
// threshold breaks at the same step.
inline void breakBonds(const FamilyView& fam, int i, const double* __restrict len, double* __restrict keep) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const double* __restrict x = fam.refLength + b0;
  const double* __restrict bn = fam.brokenN + b0;
  double* __restrict bt = fam.broken + b0;
  const double sc = fam.criticalStretch;
  double count = 0.0;
  for (int k = 0; k < n; ++k) {
    const double b = (bn[k] != 0.0 || (len[k] - x[k]) / x[k] > sc) ? 1.0 : 0.0;
    bt[k] = b;
    keep[k] = 1.0 - b;
    count += b;
  }
  // Peridigm's Damage: the plain share of broken bonds (its damage models divide by the neighbour count).
  fam.damage[i] = n > 0 ? count / n : 0.0;
}

// The same rule for one bond b of length len, for scalar loops: writes its trial flag, returns whether broken.
// The caller sets the node's Damage (the share of its bonds for which this returned true).
inline bool breakBond(const FamilyView& fam, int b, double len) {
  const bool broken = fam.brokenN[b] != 0.0 || (len - fam.refLength[b]) / fam.refLength[b] > fam.criticalStretch;
  fam.broken[b] = broken ? 1.0 : 0.0;
  return broken;
}

}  // namespace pf
