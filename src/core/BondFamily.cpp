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

}  // namespace pf
