#include "HeatConduction.hpp"

#include <cmath>

namespace pf {

HeatConduction::HeatConduction(double k, double capacity, Dimension dim, double thickness, Normalisation n)
    : k_(k), capacity_(capacity), thickness_(thickness), dim_(dim), norm_(n) {}

double HeatConduction::microconductivity(double delta) const {
  const double d2 = delta * delta;
  return isPlanar(dim_) ? 6.0 * k_ / (M_PI * thickness_ * d2 * delta) : 6.0 * k_ / (M_PI * d2 * d2);
}

// c of node i from the family sum S_i = sum_j |xi| V_j (unused by the analytic normalisation).
double HeatConduction::nodeConstant(const FamilyView& fam, double familySum) const {
  if (norm_ == Normalisation::Analytic) return microconductivity(fam.horizon);
  return familySum > 0.0 ? (isPlanar(dim_) ? 4.0 : 6.0) * k_ / familySum : 0.0;
}

void HeatConduction::apply(const FamilyView& fam, const double* u, double* out) const {
  for (int i = fam.begin; i < fam.end; ++i) {
    double sum = 0.0, familySum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      familySum += fam.refLength[b] * fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);  // broken bonds too
      if (fam.brokenN && fam.brokenN[b] != 0.0) continue;  // a broken bond conducts no heat
      sum += (u[j] - u[i]) / fam.refLength[b] * vj;
    }
    out[i] += nodeConstant(fam, familySum) * sum;
  }
}

void HeatConduction::diagonal(const FamilyView& fam, double* diag) const {
  for (int i = fam.begin; i < fam.end; ++i) {
    double sum = 0.0, familySum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      familySum += fam.refLength[b] * fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      if (fam.brokenN && fam.brokenN[b] != 0.0) continue;
      sum += vj / fam.refLength[b];
    }
    diag[i] += nodeConstant(fam, familySum) * sum;
  }
}

}  // namespace pf
