#include "ShearCorrectionFactor.hpp"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {

// Peridigm's probe strain (material_utilities.cxx): small enough for the quadratic leading term, large
// enough that sqrt(|y|^2) - |xi| keeps ~10 significant digits.
constexpr double kGamma = 1.0e-6;

// sum_j omega (e^d)^2 V_j of node i under pure shear in the (a, b) plane (Peridigm's set_pure_shear,
// then compute_norm_2_deviatoric_extension: theta from the same displaced family, node i at rest).
double deviatoricNormSquared(const FamilyView& fam, int i, int a, int b) {
  const int b0 = fam.offsets[i], b1 = fam.offsets[i + 1];
  const double* xi = fam.x + 3 * i;
  auto extension = [&](int k, double* len) {
    const int j = fam.neighbors[k];
    const double* xj = fam.x + 3 * j;
    double d[3], y[3];
    for (int c = 0; c < 3; ++c) d[c] = xj[c] - xi[c];
    // Displaced neighbour minus the node, in Peridigm's order of operations.
    for (int c = 0; c < 3; ++c) y[c] = xj[c] + (c == a ? kGamma * d[b] : c == b ? kGamma * d[a] : 0.0) - xi[c];
    *len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) - *len;
  };
  auto volume = [&](int k) { return fam.volume[fam.neighbors[k]] * (fam.fraction ? fam.fraction[k] : 1.0); };
  const double m = fam.weightedVolume[i];
  double theta = 0.0;
  for (int k = b0; k < b1; ++k) {
    double x;
    const double e = extension(k, &x);
    theta += 3.0 * fam.influence[k] * x * e * volume(k) / m;
  }
  double sum = 0.0;
  for (int k = b0; k < b1; ++k) {
    double x;
    const double ed = extension(k, &x) - theta * x / 3.0;
    sum += ed * fam.influence[k] * ed * volume(k);
  }
  return sum;
}

}  // namespace

void osbShearCorrectionFactor(const FamilyView& fam, double* scf) {
  for (int i = fam.begin; i < fam.end; ++i) {
    // Modes in Peridigm's order XY, ZX, YZ; the largest deviatoric response sets the factor.
    const double d = std::max({deviatoricNormSquared(fam, i, 0, 1), deviatoricNormSquared(fam, i, 2, 0),
                               deviatoricNormSquared(fam, i, 1, 2)});
    // Peridigm stores 4 gamma^2 m / (15 d) and its hardening model uses the inverse.
    scf[i] = d > 0.0 ? 1.0 / (4.0 * kGamma * kGamma * fam.weightedVolume[i] / d / 15.0) : 1.0;
  }
}

}  // namespace pf
