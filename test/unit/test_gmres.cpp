// The Newton step's GMRES (src/solvers/Gmres.hpp) on small dense systems, one rank: the solution against the exact
// one, one product and one preconditioner application per iteration, the residual it returns against b - A x formed
// with a product, restarts, a failed product and b = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/Gmres.hpp"

namespace pf {
namespace {

// A non-symmetric, diagonally dominant n x n matrix (a convection-diffusion stencil with a varying diagonal).
std::vector<double> matrix(int n) {
  std::vector<double> A(n * n, 0.0);
  for (int i = 0; i < n; ++i) {
    A[i * n + i] = 4.0 + 0.1 * i;
    if (i > 0) A[i * n + i - 1] = -1.5;
    if (i + 1 < n) A[i * n + i + 1] = -0.5;
    if (i + 5 < n) A[i * n + i + 5] = 0.3;
  }
  return A;
}

struct Counted {
  std::vector<double> A;
  int n, products = 0, applications = 0;
  GmresOperators ops(bool preconditioned) {
    GmresOperators op;
    op.apply = [this](const double* in, double* out) {
      ++products;
      for (int i = 0; i < n; ++i) {
        out[i] = 0;
        for (int j = 0; j < n; ++j) out[i] += A[i * n + j] * in[j];
      }
      return true;
    };
    if (preconditioned)  // Jacobi
      op.precondition = [this](const double* in, double* out) {
        ++applications;
        for (int i = 0; i < n; ++i) out[i] = in[i] / A[i * n + i];
      };
    op.sum = [](const double* in, double* out, int k) { std::copy(in, in + k, out); };
    return op;
  }
};

double relativeError(const Counted& c, const std::vector<double>& x, const std::vector<double>& b,
                     const std::vector<double>* residual = nullptr) {
  double e = 0, nb = 0;
  for (int i = 0; i < c.n; ++i) {
    double ax = 0;
    for (int j = 0; j < c.n; ++j) ax += c.A[i * c.n + j] * x[j];
    const double r = b[i] - ax - (residual ? (*residual)[i] : 0.0);
    e += r * r;
    nb += b[i] * b[i];
  }
  return std::sqrt(e / nb);
}

TEST(Gmres, SolvesWithOneProductAndOneApplicationPerIteration) {
  const int n = 60;
  Counted c{matrix(n), n};
  std::vector<double> b(n), x(n), r(n);
  for (int i = 0; i < n; ++i) b[i] = std::sin(0.3 * i) + 0.1;
  const GmresResult g = gmres(c.ops(true), b.data(), x.data(), n, 1e-10, 200, 200, r.data());
  EXPECT_TRUE(g.converged);
  EXPECT_EQ(c.products, g.iterations);
  EXPECT_EQ(c.applications, g.iterations);
  EXPECT_LE(g.relativeResidual, 1e-10);
  EXPECT_LT(relativeError(c, x, b), 1e-9);  // the true residual, within 10x the asked one (round-off)
  // r = b - A x by the Arnoldi relation, within round-off of the product's
  EXPECT_LT(relativeError(c, x, b, &r), 1e-13);
}

TEST(Gmres, RestartsAndStopsAtTheIterationLimit) {
  const int n = 60;
  Counted c{matrix(n), n};
  std::vector<double> b(n, 1.0), x(n), r(n);
  const GmresResult g = gmres(c.ops(false), b.data(), x.data(), n, 1e-10, 400, 4, r.data());
  EXPECT_TRUE(g.converged);
  EXPECT_GT(g.iterations, 4);  // restarted
  EXPECT_EQ(c.products, g.iterations);
  EXPECT_LT(relativeError(c, x, b), 1e-9);
  EXPECT_LT(relativeError(c, x, b, &r), 1e-12);
  Counted d{matrix(n), n};
  const GmresResult h = gmres(d.ops(false), b.data(), x.data(), n, 1e-14, 3, 200);
  EXPECT_FALSE(h.converged);
  EXPECT_EQ(h.iterations, 3);
  EXPECT_EQ(d.products, 3);
}

TEST(Gmres, ZeroRightHandSideAndFailedProduct) {
  const int n = 10;
  Counted c{matrix(n), n};
  std::vector<double> b(n, 0.0), x(n, 5.0);
  const GmresResult g = gmres(c.ops(true), b.data(), x.data(), n, 1e-8, 100, 100);
  EXPECT_TRUE(g.converged);
  EXPECT_EQ(g.iterations, 0);
  EXPECT_EQ(c.products, 0);
  for (double e : x) EXPECT_EQ(e, 0.0);
  GmresOperators op = c.ops(true);
  op.apply = [](const double*, double*) { return false; };
  b.assign(n, 1.0);
  const GmresResult f = gmres(op, b.data(), x.data(), n, 1e-8, 100, 100);
  EXPECT_TRUE(f.failed);
  EXPECT_FALSE(f.converged);
}

}  // namespace
}  // namespace pf
