#include "HeatConduction.hpp"

#include "MomentQuadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pf {

HeatConduction::HeatConduction(double k, double capacity, Dimension dim, double thickness, Normalisation n,
                               Quadrature q)
    : k_(k), capacity_(capacity), thickness_(thickness), dim_(dim), norm_(n), quadrature_(q) {
  if (q == Quadrature::Moments && isPlanar(dim))
    throw std::logic_error("HeatConduction: moment quadrature is three-dimensional");
}

const double* HeatConduction::bondWeights(const FamilyView& fam) const {
  if (quadrature_ == Quadrature::Volumes) return nullptr;
  auto it = weights_.find(fam.begin);
  if (it == weights_.end()) it = weights_.emplace(fam.begin, momentQuadratureWeights(fam)).first;
  return it->second.data() - fam.offsets[fam.begin];  // indexed by the bond
}

double HeatConduction::microconductivity(double delta) const {
  const double d2 = delta * delta;
  return isPlanar(dim_) ? 6.0 * k_ / (M_PI * thickness_ * d2 * delta) : 6.0 * k_ / (M_PI * d2 * d2);
}

namespace {
const char* const kFamilySum = "Conduction_Family_Sum";
}

std::string HeatConduction::nodeValueName() const { return norm_ == Normalisation::Family ? kFamilySum : ""; }

void HeatConduction::nodeValue(const FamilyView& fam, double* owned) const {
  for (int i = fam.begin; i < fam.end; ++i) {
    double S = 0.0;  // broken bonds too: the normaliser is the family's geometry
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      S += fam.refLength[b] * fam.volume[fam.neighbors[b]] * (fam.fraction ? fam.fraction[b] : 1.0);
    owned[i] = S;
  }
}

const double* HeatConduction::familySums(const FamilyView& fam) const {
  if (norm_ == Normalisation::Analytic) return nullptr;
  const double* S = fam.fields ? fam.fields->find(kFamilySum) : nullptr;
  if (!S) throw std::logic_error("HeatConduction: the model did not provide " + std::string(kFamilySum));
  return S;
}

template <class Term>
double HeatConduction::bondSum(const FamilyView& fam, const double* S, const double* w, int i, Term term) const {
  const double C = 2.0 * (isPlanar(dim_) ? 4.0 : 6.0) * k_;
  const double analytic = S ? 0.0 : microconductivity(fam.horizon);
  double sum = 0.0;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    if (fam.brokenN && fam.brokenN[b] != 0.0) continue;  // a broken bond conducts no heat
    const int j = fam.neighbors[b];
    const double c = S ? C / (S[i] + S[j]) : analytic;
    const double weight = w ? w[b] : fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
    sum += c * term(j) / fam.refLength[b] * weight;
  }
  return sum;
}

void HeatConduction::apply(const FamilyView& fam, const double* u, double* out) const {
  const double* S = familySums(fam);
  const double* w = bondWeights(fam);
  for (int i = fam.begin; i < fam.end; ++i) out[i] += bondSum(fam, S, w, i, [&](int j) { return u[j] - u[i]; });
}

void HeatConduction::diagonal(const FamilyView& fam, double* diag) const {
  const double* S = familySums(fam);
  const double* w = bondWeights(fam);
  for (int i = fam.begin; i < fam.end; ++i) diag[i] += bondSum(fam, S, w, i, [](int) { return 1.0; });
}

}  // namespace pf
