#include "SurfaceBand.hpp"

#include <cmath>

namespace pf {

void outerLayerNormals(const FamilyView& fam, bool planar, double* normal, double* layerThickness) {
  const int axes = planar ? 2 : 3;
  for (int i = fam.begin; i < fam.end; ++i) {
    double h = HUGE_VAL;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) h = std::fmin(h, fam.refLength[b]);
    layerThickness[i] = std::isfinite(h) ? h : 0.0;
    // present[a][s]: the neighbour at s h e_a exists (s = 0: minus, 1: plus); a quarter spacing absorbs round-off
    // and a slightly perturbed lattice.
    bool present[3][2] = {{false, false}, {false, false}, {false, false}};
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      double xi[3];
      for (int a = 0; a < 3; ++a) xi[a] = fam.x[3 * j + a] - fam.x[3 * i + a];
      for (int a = 0; a < axes; ++a)
        for (int s = 0; s < 2; ++s) {
          const double d0 = xi[a] - (s ? h : -h), d1 = xi[(a + 1) % 3], d2 = xi[(a + 2) % 3];
          if (d0 * d0 + d1 * d1 + d2 * d2 <= 0.0625 * h * h) present[a][s] = true;
        }
    }
    for (int a = 0; a < 3; ++a)
      normal[3 * i + a] = a < axes ? (present[a][1] ? 0.0 : 1.0) - (present[a][0] ? 0.0 : 1.0) : 0.0;
    // A point lacking both neighbours along an axis (a layer one point thick) has no outward side there.
  }
}

void spreadOneHorizon(const FamilyView& fam, const double* flag, double* flagOut) {
  for (int i = fam.begin; i < fam.end; ++i) {
    double f = flag[i];
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1] && f == 0.0; ++b) f = flag[fam.neighbors[b]];
    flagOut[i] = f != 0.0 ? 1.0 : 0.0;
  }
}

SurfaceBand buildSurfaceBand(const DistributedLayout& layout, const std::vector<FamilyView>& views,
                             const std::vector<bool>& planar) {
  const int n = layout.numOwned();
  SurfaceBand s;
  s.outerNormal.assign(3 * static_cast<std::size_t>(n), 0.0);
  s.layerThickness.assign(n, 0.0);
  for (std::size_t k = 0; k < views.size(); ++k)
    outerLayerNormals(views[k], planar[k], s.outerNormal.data(), s.layerThickness.data());
  std::vector<double> owned(n), overlap(layout.numOverlap(), 0.0);
  for (int i = 0; i < n; ++i) {
    const double* nv = &s.outerNormal[3 * i];
    owned[i] = nv[0] != 0.0 || nv[1] != 0.0 || nv[2] != 0.0 ? 1.0 : 0.0;
  }
  for (int hop = 0; hop < 2; ++hop) {  // the outer layer, then one and two horizons from it
    layout.importToOverlap(owned.data(), overlap.data(), 1);
    for (const FamilyView& v : views) spreadOneHorizon(v, overlap.data(), owned.data());
  }
  layout.importToOverlap(owned.data(), overlap.data(), 1);
  s.band = std::move(overlap);
  return s;
}

}  // namespace pf
