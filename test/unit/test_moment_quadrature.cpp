// Unit tests of the moment quadrature of heat conduction (materials/MomentQuadrature, "Use Improved Quadrature" of
// Peridigm's Diffusion): at a point on a flat surface of a cubic lattice (its family a half ball) the weights meet the
// ball's moments, so the bond sum of a linear temperature is 0 and that of T = x^2 is k lap T = 2k, where the plain
// volumes give neither (closed forms of the continuum operator, docs/thermal.md).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/HeatConduction.hpp"
#include "materials/MomentQuadrature.hpp"

namespace {

constexpr double kDx = 0.1, kDelta = 3.015 * kDx, kK = 2.5;

// Node 0 at the origin on the surface z = 0, its family the lattice points of z >= 0 within the horizon.
struct SurfacePoint {
  std::vector<double> x{0.0, 0.0, 0.0}, volume{kDx * kDx * kDx}, refLength;
  std::vector<int> offsets{0}, neighbors;
  SurfacePoint() {
    for (int i = -3; i <= 3; ++i)
      for (int j = -3; j <= 3; ++j)
        for (int k = 0; k <= 3; ++k) {
          const double r = kDx * std::sqrt(double(i * i + j * j + k * k));
          if (r == 0.0 || r > kDelta) continue;
          neighbors.push_back(static_cast<int>(volume.size()));
          refLength.push_back(r);
          x.insert(x.end(), {i * kDx, j * kDx, k * kDx});
          volume.push_back(kDx * kDx * kDx);
        }
    offsets.push_back(static_cast<int>(neighbors.size()));
  }
  pf::FamilyView view() const {
    pf::FamilyView f;
    f.begin = 0, f.end = 1, f.offsets = offsets.data(), f.neighbors = neighbors.data(), f.refLength = refLength.data();
    f.x = x.data(), f.volume = volume.data(), f.horizon = kDelta, f.numNodes = static_cast<int>(volume.size());
    return f;
  }
};

// The conduction of node 0 for the field T(x).
template <class Field>
double conduction(const SurfacePoint& p, pf::HeatConduction::Quadrature q, Field T) {
  std::vector<double> u(p.volume.size()), out(p.volume.size(), 0.0);
  for (std::size_t n = 0; n < u.size(); ++n) u[n] = T(&p.x[3 * n]);
  pf::HeatConduction h(kK, 0.0, pf::Dimension::ThreeD, 0.0, pf::HeatConduction::Normalisation::Analytic, q);
  h.apply(p.view(), u.data(), out.data());
  return out[0];
}

}  // namespace

// The weights' first and second moments are the whole ball's, 0 and pi delta^4 / 3 on the diagonal, to round-off of
// a 9 x 9 solve and a sum over 60 bonds (1e-12 of the ball's moment).
TEST(MomentQuadrature, SurfacePointMeetsTheBallsMoments) {
  const SurfacePoint p;
  const std::vector<double> w = pf::momentQuadratureWeights(p.view());
  double first[3] = {0, 0, 0}, second[3][3] = {{0}};
  for (std::size_t b = 0; b < w.size(); ++b) {
    const double* xi = &p.x[3 * p.neighbors[b]];
    for (int a = 0; a < 3; ++a) {
      first[a] += w[b] * xi[a] / p.refLength[b];
      for (int c = 0; c < 3; ++c) second[a][c] += w[b] * xi[a] * xi[c] / p.refLength[b];
    }
  }
  const double ball = M_PI * std::pow(kDelta, 4) / 3.0;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(first[a] * kDelta / ball, 0.0, 1e-12);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(second[a][c] / ball, a == c ? 1.0 : 0.0, 1e-12);
  }
}

// A linear temperature conducts no heat, T = x^2 gives k lap T = 2k (1e-12: round-off); with the volumes the surface
// point sees a flux from the linear field's gradient across the missing half (far above round-off).
TEST(MomentQuadrature, SurfaceConductionIsExactForQuadraticFields) {
  const SurfacePoint p;
  using Q = pf::HeatConduction::Quadrature;
  auto linear = [](const double* x) { return 1.0 + x[0] + 2.0 * x[1] + 3.0 * x[2]; };
  auto square = [](const double* x) { return x[0] * x[0]; };
  const double scale = 6.0 * kK / (M_PI * std::pow(kDelta, 4)) * M_PI * std::pow(kDelta, 4) / 3.0;  // = 2k
  EXPECT_NEAR(conduction(p, Q::Moments, linear) / scale, 0.0, 1e-12);
  EXPECT_NEAR(conduction(p, Q::Moments, square) / (2.0 * kK), 1.0, 1e-12);
  EXPECT_GT(std::fabs(conduction(p, Q::Volumes, linear)) / scale, 1.0);
}
