// The exact tangent (osbElasticForceDerivative, used by NOXQuasiStatic) against central finite
// differences of the force, at a deformed state with a large rigid rotation and a small strain, in 3D,
// plane stress and plane strain.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "LatticeFixture.hpp"
#include "materials/OsbKernels.hpp"

namespace {

struct Case {
  pf::Dimension dim;
  bool planar;
};

TEST(ExactTangent, MatchesFiniteDifferencesUnderLargeRotation) {
  for (Case cs : {Case{pf::Dimension::ThreeD, false}, Case{pf::Dimension::PlaneStress, true},
                  Case{pf::Dimension::PlaneStrain, true}}) {
    const double dx = 1e-3;
    pftest::Lattice L = pftest::makeLattice(7, cs.planar, dx, 3.015, 1e-3, pf::Influence::One, false);
    auto mat = pftest::makeElastic(cs.dim, 200e9, 0.3, 1e-3);
    const int n = L.numNodes;
    // deformed state: rotate 60 degrees about z after a random small strain
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    std::vector<double> y(3 * n), dy(3 * n);
    const double c = std::cos(M_PI / 3), s = std::sin(M_PI / 3);
    for (int p = 0; p < n; ++p) {
      double q[3];
      for (int a = 0; a < 3; ++a) q[a] = L.x[3 * p + a] * (1.0 + 1e-3 * U(rng));
      if (cs.planar) q[2] = 0.0;
      y[3 * p] = c * q[0] - s * q[1];
      y[3 * p + 1] = s * q[0] + c * q[1];
      y[3 * p + 2] = q[2];
      for (int a = 0; a < 3; ++a) dy[3 * p + a] = (cs.planar && a == 2) ? 0.0 : U(rng) * dx;
    }
    const pf::OsbConstants& k = mat->constants();
    auto force = [&](const std::vector<double>& pos) {
      std::vector<double> theta(n), f(3 * n, 0.0);
      pf::osbDilatation(L.view(), k, pos.data(), nullptr, theta.data());
      pf::osbElasticForce(L.view(), k, pos.data(), theta.data(), f.data());
      return f;
    };
    std::vector<double> exact(3 * n, 0.0);
    pf::osbElasticForceDerivative(L.view(), k, y.data(), dy.data(), exact.data());
    // central difference, step 1e-7 of dx: truncation O(h^2) ~ 1e-14 relative, round-off ~1e-16/1e-7
    const double h = 1e-7;
    std::vector<double> yp(y), ym(y);
    for (int q = 0; q < 3 * n; ++q) {
      yp[q] += h * dy[q];
      ym[q] -= h * dy[q];
    }
    const std::vector<double> fp = force(yp), fm = force(ym);
    double err = 0, scale = 0;
    for (int q = 0; q < 3 * n; ++q) {
      const double fd = (fp[q] - fm[q]) / (2 * h);
      err = std::max(err, std::fabs(fd - exact[q]));
      scale = std::max(scale, std::fabs(exact[q]));
    }
    std::printf("[ExactTangent] %s: max |J dy - FD| / max |J dy| = %.2e\n", pf::toString(cs.dim), err / scale);
    // 1e-6: the FD round-off bound (1e-16 x force scale / 1e-7 step, amplified by cancellation in the
    // bond sums); a wrong term of the derivative (e.g. the rotation part t dM) shows at the 1e-1 level.
    EXPECT_LT(err / scale, 1e-6) << pf::toString(cs.dim);
  }
}

}  // namespace
