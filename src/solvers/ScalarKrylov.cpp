#include "ScalarKrylov.hpp"

#include <cmath>

namespace pf {

ScalarKrylovResult bicgstab(const std::function<void(const double*, double*)>& apply,
                            const std::vector<double>& inverseDiagonal, const std::vector<double>& b,
                            std::vector<double>& x, double tol, int maxIterations,
                            const std::function<double(double)>& sum) {
  const std::size_t n = b.size();
  auto dot = [&](const std::vector<double>& a, const std::vector<double>& c) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += a[i] * c[i];
    return sum(s);
  };
  x.assign(n, 0.0);
  std::vector<double> r = b, r0 = b, p(n, 0.0), v(n, 0.0), s(n), t(n), ph(n), sh(n);
  const double bnorm = std::sqrt(dot(b, b));
  ScalarKrylovResult out;
  if (bnorm == 0.0) return {true, 0, 0.0};
  double rho = 1.0, alpha = 1.0, omega = 1.0;
  for (int it = 1; it <= maxIterations; ++it) {
    const double rhoNew = dot(r0, r);
    if (rhoNew == 0.0) break;  // breakdown: report what we have
    const double beta = (rhoNew / rho) * (alpha / omega);
    rho = rhoNew;
    for (std::size_t i = 0; i < n; ++i) p[i] = r[i] + beta * (p[i] - omega * v[i]);
    for (std::size_t i = 0; i < n; ++i) ph[i] = inverseDiagonal[i] * p[i];
    apply(ph.data(), v.data());
    alpha = rho / dot(r0, v);
    for (std::size_t i = 0; i < n; ++i) s[i] = r[i] - alpha * v[i];
    out.iterations = it;
    if (std::sqrt(dot(s, s)) <= tol * bnorm) {
      for (std::size_t i = 0; i < n; ++i) x[i] += alpha * ph[i];
      r = s;
      out.converged = true;
      break;
    }
    for (std::size_t i = 0; i < n; ++i) sh[i] = inverseDiagonal[i] * s[i];
    apply(sh.data(), t.data());
    const double tt = dot(t, t);
    omega = tt > 0.0 ? dot(t, s) / tt : 0.0;
    for (std::size_t i = 0; i < n; ++i) x[i] += alpha * ph[i] + omega * sh[i];
    for (std::size_t i = 0; i < n; ++i) r[i] = s[i] - omega * t[i];
    if (std::sqrt(dot(r, r)) <= tol * bnorm) {
      out.converged = true;
      break;
    }
    if (omega == 0.0) break;
  }
  out.residual = std::sqrt(dot(r, r));
  return out;
}

}  // namespace pf
