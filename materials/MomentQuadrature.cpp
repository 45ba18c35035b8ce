#include "MomentQuadrature.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace pf {

namespace {

constexpr int kMoments = 9;  // x, y, z, xx, xy, xz, yy, yz, zz

// The moment functions of a bond in units of the horizon (so that the first and second moments are of one size
// and the normal matrix is well scaled at any horizon): e = xi / delta, each over |e|.
Eigen::Matrix<double, kMoments, 1> moments(const double* xi, double delta) {
  const double e[3] = {xi[0] / delta, xi[1] / delta, xi[2] / delta};
  const double r = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  Eigen::Matrix<double, kMoments, 1> m;
  m << e[0], e[1], e[2], e[0] * e[0], e[0] * e[1], e[0] * e[2], e[1] * e[1], e[1] * e[2], e[2] * e[2];
  return m / r;
}

}  // namespace

std::vector<double> momentQuadratureWeights(const FamilyView& fam) {
  const int first = fam.offsets[fam.begin];
  std::vector<double> w(static_cast<std::size_t>(fam.offsets[fam.end] - first));
  const double delta = fam.horizon;
  Eigen::Matrix<double, kMoments, 1> ball = Eigen::Matrix<double, kMoments, 1>::Zero();
  ball(3) = ball(6) = ball(8) = M_PI * delta * delta * delta / 3.0;  // the header's pi delta^4 / 3, over delta
  for (int i = fam.begin; i < fam.end; ++i) {
    Eigen::Matrix<double, kMoments, kMoments> G = Eigen::Matrix<double, kMoments, kMoments>::Zero();
    Eigen::Matrix<double, kMoments, 1> missing = ball;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double xi[3] = {fam.x[3 * j] - fam.x[3 * i], fam.x[3 * j + 1] - fam.x[3 * i + 1], fam.x[3 * j + 2] - fam.x[3 * i + 2]};
      const double V = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      const Eigen::Matrix<double, kMoments, 1> m = moments(xi, delta);
      G.noalias() += V * m * m.transpose();
      missing -= V * m;
      w[static_cast<std::size_t>(b - first)] = V;
    }
    // w = V + V (m . lambda) with G lambda = the moments the volumes miss.
    Eigen::LDLT<Eigen::Matrix<double, kMoments, kMoments>> ldlt(G);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 1e-12 * ldlt.vectorD().maxCoeff())
      continue;  // a flat or one-sided family: keep the volumes
    const Eigen::Matrix<double, kMoments, 1> lambda = ldlt.solve(missing);
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double xi[3] = {fam.x[3 * j] - fam.x[3 * i], fam.x[3 * j + 1] - fam.x[3 * i + 1], fam.x[3 * j + 2] - fam.x[3 * i + 2]};
      w[static_cast<std::size_t>(b - first)] *= 1.0 + moments(xi, delta).dot(lambda);
    }
  }
  return w;
}

}  // namespace pf
