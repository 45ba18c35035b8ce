#include "OsbThermalKernels.hpp"

#include <cmath>

#include "core/BondDamage.hpp"

namespace pf {

void osbThermoelasticDilatationAndForce(const FamilyView& fam, const OsbConstants& c, double a, const double* dT,
                                        const double* y, double* theta, double* force) {
  const double* V = fam.volume;
  const bool damaged = fam.brokenN != nullptr;
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], b1 = fam.offsets[i + 1];
    const double strain = a * dT[i];  // free thermal stretch of node i's bonds
    const double* yi = y + 3 * i;
    // Pass 1: breaks (on the mechanical stretch) and the dilatation of the mechanical extension (Eq. 4).
    double sum = 0.0, broken = 0.0;
    for (int b = b0; b < b1; ++b) {
      const int j = fam.neighbors[b];
      const double d0 = y[3 * j] - yi[0], d1 = y[3 * j + 1] - yi[1], d2 = y[3 * j + 2] - yi[2];
      const double xi = fam.refLength[b], eth = strain * xi;
      const double len = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
      if (damaged) {
        const bool br = bondBroken(fam.brokenN[b], len - eth, xi, fam.criticalStretch);
        fam.broken[b] = br ? 1.0 : 0.0;
        if (br) {
          broken += 1.0;
          continue;
        }
      }
      const double vj = V[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      sum += fam.influence[b] * xi * (len - xi - eth) * vj;
    }
    if (damaged) finishNode(fam, i, b1 - b0, broken);
    const double m = fam.weightedVolume[i];
    theta[i] = b1 > b0 && m > 0.0 ? c.k * c.D * sum / m : 0.0;
    if (!(m > 0.0)) continue;
    // Pass 2: t = omega (A theta x / m + B e^d / m), e^d = (e - e_th) - c theta x (Eqs. 3, 9-13).
    const double iso = (c.A - c.B * c.c) * theta[i] / m, dev = c.B / m;
    for (int b = b0; b < b1; ++b) {
      if (damaged && fam.broken[b] != 0.0) continue;
      const int j = fam.neighbors[b];
      const double d[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
      const double xi = fam.refLength[b];
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      const double t = fam.influence[b] * (iso * xi + dev * (len - xi - strain * xi));
      const double fr = fam.fraction ? fam.fraction[b] : 1.0;
      for (int e = 0; e < 3; ++e) {
        const double s = t * d[e] / len;
        force[3 * i + e] += s * V[j] * fr;
        force[3 * j + e] -= s * V[i] * fr;
      }
    }
  }
}

}  // namespace pf
