#include "HeatConduction.hpp"

#include <cmath>

namespace pf {

HeatConduction::HeatConduction(double k, double capacity, Dimension dim, double thickness, Normalisation n)
    : k_(k), capacity_(capacity), thickness_(thickness), dim_(dim), norm_(n) {}

double HeatConduction::nodeConstant(const FamilyView& fam, int i) const {
  if (norm_ == Normalisation::Analytic) return microconductivity(fam.horizon);
  double s = 0.0;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
    s += fam.refLength[b] * fam.volume[fam.neighbors[b]] * (fam.fraction ? fam.fraction[b] : 1.0);
  return s > 0.0 ? (isPlanar(dim_) ? 4.0 : 6.0) * k_ / s : 0.0;
}

double HeatConduction::microconductivity(double delta) const {
  const double d2 = delta * delta;
  return isPlanar(dim_) ? 6.0 * k_ / (M_PI * thickness_ * d2 * delta) : 6.0 * k_ / (M_PI * d2 * d2);
}

void HeatConduction::apply(const FamilyView& fam, const double* u, double* out) const {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = nodeConstant(fam, i);
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      if (fam.brokenN && fam.brokenN[b] != 0.0) continue;  // a broken bond conducts no heat
      const int j = fam.neighbors[b];
      const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      sum += (u[j] - u[i]) / fam.refLength[b] * vj;
    }
    out[i] += c * sum;
  }
}

void HeatConduction::diagonal(const FamilyView& fam, double* diag) const {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double c = nodeConstant(fam, i);
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      if (fam.brokenN && fam.brokenN[b] != 0.0) continue;
      const int j = fam.neighbors[b];
      sum += fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0) / fam.refLength[b];
    }
    diag[i] += c * sum;
  }
}

}  // namespace pf
