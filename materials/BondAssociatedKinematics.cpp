#include "BondAssociatedKinematics.hpp"

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

}  // namespace pf
