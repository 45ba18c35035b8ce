#include "BondFamily.hpp"

namespace pf {

void computeWeightedVolume(const FamilyView& fam, double* m) {
  for (int i = fam.begin; i < fam.end; ++i) {
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const double r = fam.refLength[b];
      const double w = fam.fraction ? fam.influence[b] * fam.fraction[b] : fam.influence[b];
      sum += w * r * r * fam.volume[fam.neighbors[b]];
    }
    m[i] = sum;
  }
}

void keepBonds(BondFamily& family, const std::function<bool(int, int)>& keep) {
  const bool partial = !family.fraction.empty();
  std::size_t out = 0;
  int begin = 0;
  for (int i = 0; i < family.numOwned(); ++i) {
    const int end = family.offsets[i + 1];
    for (int b = begin; b < end; ++b)
      if (keep(i, family.neighbors[b])) {
        family.neighbors[out] = family.neighbors[b];
        family.refLength[out] = family.refLength[b];
        if (partial) family.fraction[out] = family.fraction[b];
        ++out;
      }
    begin = end;
    family.offsets[i + 1] = static_cast<int>(out);
  }
  family.neighbors.resize(out);
  family.refLength.resize(out);
  if (partial) family.fraction.resize(out);
}

}  // namespace pf
