#include "BondAssociatedKinematics.hpp"

#include <cmath>

#include "core/ShapeTensor.hpp"

namespace pf {

Mat3 bondGradient(const Mat3& Fi, const Mat3& Fj, const double* xi, const double* Y) {
  const double l2 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
  Mat3 F = 0.5 * (Fi + Fj);
  for (int a = 0; a < 3; ++a) {
    const double gap = Y[a] - (F[3 * a] * xi[0] + F[3 * a + 1] * xi[1] + F[3 * a + 2] * xi[2]);
    for (int c = 0; c < 3; ++c) F[3 * a + c] += gap * xi[c] / l2;
  }
  return F;
}

Mat3 normalProjector(const double* xi) {
  const double l2 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
  Mat3 p = identity3();
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) p[3 * a + c] -= xi[a] * xi[c] / l2;
  return p;
}

void bondForceState(const Mat3& P, const Mat3& S, const Mat3& Kinv, const double* xi, double omega, double w0,
                    double* T) {
  const double l2 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
  double phi[3];
  for (int a = 0; a < 3; ++a) phi[a] = omega * (Kinv[3 * a] * xi[0] + Kinv[3 * a + 1] * xi[1] + Kinv[3 * a + 2] * xi[2]);
  for (int a = 0; a < 3; ++a)
    T[a] = omega / w0 * (P[3 * a] * xi[0] + P[3 * a + 1] * xi[1] + P[3 * a + 2] * xi[2]) / l2 +
           S[3 * a] * phi[0] + S[3 * a + 1] * phi[1] + S[3 * a + 2] * phi[2];
}

// |dP/dH| <= max(3K, 2mu); a bond's T moves with its own P by about omega/w0 |xi|^-1 and with the stress integral
// through phi: the same a_i = sum omega |K^-1 xi| V_j bound as the other correspondence models, plus the direct term.
void bondAssociatedStiffnessBound(const FamilyView& fam, double C, double* bound) {
  for (int i = fam.begin; i < fam.end; ++i) {
    ShapeAndGradient sg;
    const Mat3 Kinv = tryShapeAndGradient(fam, i, fam.x, false, sg) ? sg.Kinv : Mat3{};
    double a = 0.0, w0 = 0.0, direct = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = bondWeight(fam, b);
      double kx[3] = {0, 0, 0};
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) kx[r] += Kinv[3 * r + s] * (fam.x[3 * j + s] - fam.x[3 * i + s]);
      a += w * std::sqrt(kx[0] * kx[0] + kx[1] * kx[1] + kx[2] * kx[2]);
      w0 += w;
      direct += w / (fam.refLength[b] * fam.refLength[b]);
    }
    bound[i] = 4.0 * C * a * a + (w0 > 0.0 ? 4.0 * C * direct / w0 : 0.0);
  }
}

}  // namespace pf
