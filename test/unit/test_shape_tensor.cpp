// Unit tests of core/ShapeTensor (the kinematics behind the Deformation_Gradient and Shape_Tensor_Inverse outputs,
// Model::kinematicTensors) and of the tensor output names (core/OutputFields), against closed forms:
//  1. K of the centre of a cubic lattice with unit influence is diagonal, K_aa = V sum over the family's lattice
//     offsets of (k dx)^2 (counted here by brute force), so K^-1 is its reciprocal; planar: the same in-plane, zz = 0;
//  2. an affine motion y = A x + c gives F = A to round-off at every point whose K is regular, boundary points
//     included (N = A K bond by bond);
//  3. a quadratic motion y = x + q(x) has F = I at the centre of a point-symmetric family (the third moments of
//     the family vanish), the exact gradient there;
//  4. Peridigm's component names XX, XY, ..., ZZ (row-major) and the transposed name of a symmetric tensor.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/OutputFields.hpp"
#include "core/ShapeTensor.hpp"

namespace {

constexpr double kDx = 1e-3;

// sum of (k_a dx)^2 over the lattice offsets k != 0 with |k| dx <= horizon (the family of the centre).
double secondMoment(double ratio, bool planar, int axis) {
  const int r = static_cast<int>(std::ceil(ratio)) + 1;
  double s = 0.0;
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j)
      for (int k = (planar ? 0 : -r); k <= (planar ? 0 : r); ++k) {
        const int n2 = i * i + j * j + k * k;
        if (n2 == 0 || std::sqrt(static_cast<double>(n2)) > ratio) continue;
        const int c = axis == 0 ? i : axis == 1 ? j : k;
        s += c * c * kDx * kDx;
      }
  return s;
}

TEST(ShapeTensorKernel, ShapeTensorInverseOfLatticeCentre) {
  for (bool planar : {false, true}) {
    const double ratio = 3.015;  // a horizon just past 3 dx, as Peridigm's decks take it
    const pftest::Lattice L = pftest::makeLattice(9, planar, kDx, ratio, kDx, pf::Influence::One, true);
    pf::ShapeAndGradient sg;
    ASSERT_TRUE(pf::tryShapeAndGradient(L.view(), 0, L.x.data(), planar, sg));
    const int d = planar ? 2 : 3;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double expected = (a == b && a < d) ? 1.0 / (L.nodeVolume() * secondMoment(ratio, planar, a)) : 0.0;
        // round-off of a sum of ~100 positive terms relative to the diagonal
        EXPECT_NEAR(sg.Kinv[3 * a + b], expected, 1e-12 * std::fabs(sg.Kinv[0])) << "planar " << planar << " " << a << b;
      }
  }
}

TEST(ShapeTensorKernel, AffineMotionGivesItsGradientEverywhere) {
  const pf::Mat3 A = {1.02, 0.03, -0.01, -0.04, 0.97, 0.05, 0.02, -0.03, 1.01};
  const pftest::Lattice L = pftest::makeLattice(5, false, kDx, 2.015, kDx, pf::Influence::Gaussian, false);
  std::vector<double> y(L.x.size());
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < 3; ++a)
      y[3 * p + a] = 1e-4 * (a + 1) + A[3 * a] * L.x[3 * p] + A[3 * a + 1] * L.x[3 * p + 1] + A[3 * a + 2] * L.x[3 * p + 2];
  const pf::FamilyView fam = L.view();
  for (int i = 0; i < L.numQueries; ++i) {
    pf::ShapeAndGradient sg;
    ASSERT_TRUE(pf::tryShapeAndGradient(fam, i, y.data(), false, sg)) << "point " << i;
    for (int c = 0; c < 9; ++c) EXPECT_NEAR(sg.F[c], A[c], 1e-12) << "point " << i << " component " << c;  // round-off
  }
}

TEST(ShapeTensorKernel, QuadraticMotionHasTheExactGradientAtASymmetricCentre) {
  const pftest::Lattice L = pftest::makeLattice(9, false, kDx, 3.015, kDx, pf::Influence::One, true);
  std::vector<double> y(L.x.size());
  for (int p = 0; p < L.numNodes; ++p) {
    const double* x = &L.x[3 * p];
    y[3 * p] = x[0] + 30.0 * x[1] * x[2];
    y[3 * p + 1] = x[1] - 20.0 * x[0] * x[0];
    y[3 * p + 2] = x[2] + 10.0 * x[1] * x[1];
  }
  pf::ShapeAndGradient sg;
  ASSERT_TRUE(pf::tryShapeAndGradient(L.view(), 0, y.data(), false, sg));
  for (int c = 0; c < 9; ++c) EXPECT_NEAR(sg.F[c], c % 4 == 0 ? 1.0 : 0.0, 1e-12) << "component " << c;
}

TEST(TensorOutputNames, PeridigmOrderAndTransposes) {
  const std::vector<std::string> expected = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
  EXPECT_EQ(pf::tensorComponentSuffixes(), expected);
  EXPECT_EQ(pf::transposedComponentName("Unrotated_Cauchy_StressYX"), "Unrotated_Cauchy_StressXY");
  EXPECT_EQ(pf::transposedComponentName("Cauchy_StressZZ"), "Cauchy_StressZZ");
  EXPECT_EQ(pf::transposedComponentName("Damage"), "Damage");
  EXPECT_TRUE(pf::isTensorField("Deformation_Gradient"));
  EXPECT_TRUE(pf::isKinematicTensor("Shape_Tensor_Inverse"));
  EXPECT_FALSE(pf::isKinematicTensor("Rotation_Tensor"));
  EXPECT_FALSE(pf::isTensorField("Deformation_GradientXX"));
}

}  // namespace
