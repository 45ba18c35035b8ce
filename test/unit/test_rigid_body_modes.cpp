// RigidBodyModes (the near-null space MueLu gets for the Newton step's preconditioner) against what a rigid motion
// is, independently of how the modes are written: an infinitesimal rigid motion v keeps every distance to first
// order, (v_p - v_q) . (x_p - x_q) = 0 for all pairs; the modes are independent; and every rigid motion
// t + w x x (3D) or in-plane one (planar) is a combination of them.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <random>
#include <vector>

#include "solvers/RigidBodyModes.hpp"

namespace {

std::vector<double> cloud(int n, bool planar, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  std::vector<double> x(3 * n);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) x[3 * i + d] = (planar && d == 2) ? 0.5 : u(rng);
  return x;
}

Eigen::MatrixXd asMatrix(const pf::RigidBodyModes& m, int n) {
  Eigen::MatrixXd B(3 * n, m.count);
  for (int k = 0; k < m.count; ++k)
    for (int r = 0; r < 3 * n; ++r) B(r, k) = m.values[k * 3 * n + r];
  return B;
}

// The largest |(v_p - v_q) . (x_p - x_q)| over all pairs (absolute: coordinates and modes are O(1) to O(5)).
double worstStretchRate(const std::vector<double>& x, const double* v, int n) {
  double worst = 0;
  for (int p = 0; p < n; ++p)
    for (int q = p + 1; q < n; ++q) {
      double dot = 0;
      for (int d = 0; d < 3; ++d) dot += (v[3 * p + d] - v[3 * q + d]) * (x[3 * p + d] - x[3 * q + d]);
      worst = std::max(worst, std::abs(dot));
    }
  return worst;
}

void expectRigidBasis(bool planar) {
  const int n = 40;
  const std::vector<double> x = cloud(n, planar, planar ? 7u : 3u);
  const double centre[3] = {0.3, -1.1, 0.5};
  const pf::RigidBodyModes modes = pf::rigidBodyModes(x.data(), n, centre, planar);
  ASSERT_EQ(modes.count, planar ? 4 : 6);
  ASSERT_EQ(modes.values.size(), static_cast<std::size_t>(modes.count * 3 * n));
  // Distances kept to first order: exact up to round-off of coordinates of size ~5 (products ~25).
  for (int k = 0; k < modes.count; ++k)
    EXPECT_LT(worstStretchRate(x, &modes.values[k * 3 * n], n), 1e-12) << "mode " << k;
  const Eigen::MatrixXd B = asMatrix(modes, n);
  // Independent: the smallest singular value well away from zero (the modes are O(1) to O(5) per entry).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(B);
  EXPECT_GT(svd.singularValues().minCoeff(), 1.0);
  // Complete: a rigid motion with its own translation and rotation (about the origin, not the centre) lies in
  // the span to round-off.
  const double t[3] = {0.7, -0.2, planar ? 0.0 : 1.3}, w[3] = {planar ? 0.0 : 0.4, planar ? 0.0 : -0.9, 0.25};
  Eigen::VectorXd u(3 * n);
  for (int i = 0; i < n; ++i) {
    const double* p = &x[3 * i];
    u(3 * i) = t[0] + w[1] * p[2] - w[2] * p[1];
    u(3 * i + 1) = t[1] + w[2] * p[0] - w[0] * p[2];
    u(3 * i + 2) = t[2] + w[0] * p[1] - w[1] * p[0];
  }
  const Eigen::VectorXd c = B.colPivHouseholderQr().solve(u);
  EXPECT_LT((B * c - u).norm(), 1e-12 * u.norm());
  if (planar) {  // no rotation moves z (the planar models carry no z motion); the z rows keep their translation
    for (int k = 0; k < modes.count; ++k)
      for (int i = 0; i < n; ++i) EXPECT_EQ(modes.values[k * 3 * n + 3 * i + 2], k == 2 ? 1.0 : 0.0);
  }
}

}  // namespace

TEST(RigidBodyModes, ThreeDimensionalModesAreAnIndependentCompleteSetOfRigidMotions) { expectRigidBasis(false); }

TEST(RigidBodyModes, PlanarModesAreTheTranslationsAndTheRotationAboutZ) { expectRigidBasis(true); }
