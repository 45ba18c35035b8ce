#include "Gmres.hpp"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// One restart cycle's Arnoldi basis V, the preconditioned basis Z = M⁻¹ V, and the Hessenberg matrix reduced by
// Givens rotations to R (column-major, m + 1 rows); g: the rotated right-hand side β e1.
struct Cycle {
  std::size_t n;
  int m;
  std::vector<std::vector<double>> V, Z;  // grown as the iterations need them (most solves take few)
  std::vector<double> H, cs, sn, g, y, dots, sums;
  Cycle(std::size_t n_, int m_)
      : n(n_), m(m_), H((m_ + 1) * m_), cs(m_), sn(m_), g(m_ + 1), y(m_), dots(m_ + 2), sums(m_ + 2) {}
  double& h(int i, int j) { return H[static_cast<std::size_t>(j) * (m + 1) + i]; }
};

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// w = V[k + 1] against V[0..k]: classical Gram-Schmidt with a second pass when the first cancelled much of w (DGKS,
// Belos' default), one reduction per pass instead of one per basis vector. Column k of H gets the coefficients and
// |w|; w is normalised.
void orthogonalise(const GmresOperators& op, Cycle& c, int k) {
  std::vector<double>& w = c.V[k + 1];
  for (int j = 0; j <= k + 1; ++j) c.h(j, k) = 0.0;
  for (int pass = 0; pass < 2; ++pass) {
    for (int j = 0; j <= k; ++j) c.dots[j] = dot(c.V[j], w);
    c.dots[k + 1] = dot(w, w);
    op.sum(c.dots.data(), c.sums.data(), k + 2);
    const double before = std::sqrt(c.sums[k + 1]);
    for (int j = 0; j <= k; ++j) {
      c.h(j, k) += c.sums[j];
      const double* v = c.V[j].data();
      for (std::size_t i = 0; i < c.n; ++i) w[i] -= c.sums[j] * v[i];
    }
    const double local = dot(w, w);
    double after = 0;
    op.sum(&local, &after, 1);
    after = std::sqrt(after);
    c.h(k + 1, k) = after;
    if (after > 0.7071067811865476 * before) break;
  }
  if (c.h(k + 1, k) > 0.0)
    for (double& e : w) e /= c.h(k + 1, k);
}

// The earlier rotations and a new one on column k; returns the new diagonal (0: a singular column).
double rotate(Cycle& c, int k) {
  for (int j = 0; j < k; ++j) {
    const double a = c.h(j, k), b = c.h(j + 1, k);
    c.h(j, k) = c.cs[j] * a + c.sn[j] * b;
    c.h(j + 1, k) = -c.sn[j] * a + c.cs[j] * b;
  }
  const double d = std::hypot(c.h(k, k), c.h(k + 1, k));
  c.cs[k] = d > 0 ? c.h(k, k) / d : 1.0;
  c.sn[k] = d > 0 ? c.h(k + 1, k) / d : 0.0;
  c.h(k, k) = d;
  c.h(k + 1, k) = 0.0;
  c.g[k + 1] = -c.sn[k] * c.g[k];
  c.g[k] = c.cs[k] * c.g[k];
  return d;
}

// After k iterations: x += Z R⁻¹ g, and r = b - A x = V Q^T (0, ..., 0, g_k) (the rotations undone on g's last
// entry; no product).
void finishCycle(Cycle& c, int k, double* x, std::vector<double>& r) {
  for (int i = k - 1; i >= 0; --i) {
    double s = c.g[i];
    for (int j = i + 1; j < k; ++j) s -= c.h(i, j) * c.y[j];
    c.y[i] = c.h(i, i) != 0.0 ? s / c.h(i, i) : 0.0;
  }
  for (int j = 0; j < k; ++j)
    for (std::size_t i = 0; i < c.n; ++i) x[i] += c.y[j] * c.Z[j][i];
  std::fill(c.dots.begin(), c.dots.end(), 0.0);
  c.dots[k] = c.g[k];
  for (int j = k - 1; j >= 0; --j) {
    const double a = c.dots[j], b = c.dots[j + 1];
    c.dots[j] = c.cs[j] * a - c.sn[j] * b;
    c.dots[j + 1] = c.sn[j] * a + c.cs[j] * b;
  }
  std::fill(r.begin(), r.end(), 0.0);
  for (int j = 0; j <= k; ++j)
    for (std::size_t i = 0; i < c.n; ++i) r[i] += c.dots[j] * c.V[j][i];
}

}  // namespace

GmresResult gmres(const GmresOperators& op, const double* b, double* x, std::size_t n, double tol, int maxIterations,
                  int restart, double* residual) {
  GmresResult out;
  std::fill(x, x + n, 0.0);
  std::vector<double> r(b, b + n);
  auto norm = [&](const std::vector<double>& v) {
    const double local = dot(v, v);
    double global = 0;
    op.sum(&local, &global, 1);
    return std::sqrt(global);
  };
  const double bnorm = norm(r);
  double beta = bnorm;
  Cycle c(n, std::max(1, std::min(restart, std::max(1, maxIterations))));
  bool done = !(bnorm > 0.0);  // b = 0: x = 0 is the solution; a NaN is not converged
  out.converged = bnorm == 0.0;
  out.relativeResidual = out.converged ? 0.0 : 1.0;
  while (!done) {
    if (c.V.empty()) c.V.emplace_back(n);
    for (std::size_t i = 0; i < n; ++i) c.V[0][i] = r[i] / beta;
    std::fill(c.g.begin(), c.g.end(), 0.0);
    c.g[0] = beta;
    int k = 0;
    bool stalled = false;
    while (k < c.m && out.iterations < maxIterations && !out.converged && !stalled) {
      if (static_cast<int>(c.Z.size()) <= k) c.Z.emplace_back(n);
      if (static_cast<int>(c.V.size()) <= k + 1) c.V.emplace_back(n);
      if (op.precondition)
        op.precondition(c.V[k].data(), c.Z[k].data());
      else
        c.Z[k] = c.V[k];
      if (!op.apply(c.Z[k].data(), c.V[k + 1].data())) {
        out.failed = true;
        return out;
      }
      ++out.iterations;
      orthogonalise(op, c, k);
      stalled = rotate(c, k) == 0.0;  // a singular Hessenberg column: no progress from here
      ++k;
      out.relativeResidual = std::fabs(c.g[k]) / bnorm;
      out.converged = out.relativeResidual <= tol;
    }
    finishCycle(c, k, x, r);
    done = out.converged || stalled || out.iterations >= maxIterations;
    if (!done) beta = norm(r);  // restart from the residual of the cycle's update
    if (!done && !(beta > 0.0)) out.converged = done = true;
  }
  if (residual) std::copy(r.begin(), r.end(), residual);
  return out;
}

}  // namespace pf
