#include "OsbKernels.hpp"

#include <algorithm>
#include <cmath>

namespace pf {

void osbDilatation(const FamilyView& fam, const OsbConstants& c, const double* y, const double* edp,
                   double* theta) {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double d0 = y[3 * j] - yi0, d1 = y[3 * j + 1] - yi1, d2 = y[3 * j + 2] - yi2;
      const double x = fam.refLength[b];
      double e = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2) - x;
      if (edp) e -= edp[b];
      sum += fam.influence[b] * x * e * fam.volume[j];
    }
    theta[i] = c.k * c.D * sum / fam.weightedVolume[i];
  }
}

void osbElasticForce(const FamilyView& fam, const OsbConstants& c, const double* y, const double* theta,
                     double* force) {
  const double* V = fam.volume;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
    const double invm = 1.0 / fam.weightedVolume[i];
    const double iso = (c.A - c.B * c.c) * theta[i] * invm;  // coefficient of omega x
    const double dev = c.B * invm;                          // coefficient of omega e
    double fi0 = 0, fi1 = 0, fi2 = 0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double d0 = y[3 * j] - yi0, d1 = y[3 * j + 1] - yi1, d2 = y[3 * j + 2] - yi2;
      const double len = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
      const double x = fam.refLength[b];
      const double t = fam.influence[b] * (iso * x + dev * (len - x));
      const double s = t / len;
      fi0 += s * d0 * V[j]; fi1 += s * d1 * V[j]; fi2 += s * d2 * V[j];
      force[3 * j] -= s * d0 * V[i]; force[3 * j + 1] -= s * d1 * V[i]; force[3 * j + 2] -= s * d2 * V[i];
    }
    force[3 * i] += fi0; force[3 * i + 1] += fi1; force[3 * i + 2] += fi2;
  }
}

void osbPairStiffness(const FamilyView& fam, const OsbConstants& c, double* stiffness) {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double scale = c.B / fam.weightedVolume[i];
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) stiffness[b] = scale * fam.influence[b];
  }
}

void osbStiffnessBound(const FamilyView& fam, const OsbConstants& c, double* bound) {
  const double coupling = std::fabs(c.A - c.B * c.c) * c.k * c.D;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double m = fam.weightedVolume[i];
    double S = 0.0;  // sum omega x V: scale of d theta / d e
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      S += fam.influence[b] * fam.refLength[b] * fam.volume[fam.neighbors[b]];
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = fam.influence[b], x = fam.refLength[b], Vj = fam.volume[j];
      // A bond along n couples component a to all three: sum_b |n_a n_b| = |n_a| |n|_1 <= max_a of it.
      double n[3], n1 = 0.0, nmax = 0.0;
      for (int d = 0; d < 3; ++d) {
        n[d] = std::fabs(fam.x[3 * j + d] - fam.x[3 * i + d]) / x;
        n1 += n[d];
        nmax = std::max(nmax, n[d]);
      }
      // t_ij (through m_i) and t_ji (through m_j) both load node i; the dilatation coupling of t_ji runs
      // over j's family, bounded here by i's sum S with the smaller of the two weighted volumes.
      const double mj = fam.weightedVolume[j], mmin = std::min(m, mj);
      sum += Vj * w * nmax * n1 * (c.B / m + c.B / mj + 2.0 * coupling * x * S / (m * mmin));
    }
    bound[i] = 2.0 * sum;
  }
}

}  // namespace pf
