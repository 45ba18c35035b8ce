#pragma once
// An independent Drucker-Prager reference for the material-point tests of "Drucker Prager Correspondence":
// a general-purpose backward-Euler return in principal stresses (fixed principal axes), written in the
// classical tension-positive form
//   f(sigma, m) = sqrt(J2) + m alpha I1 - m k,   g(sigma, m) = sqrt(J2) + m d0 alpha I1 - m k,
// with the hardening law of the model m(xi) = m0 + h (1 - m0) xi / (1 - m0 + h xi) and the PIV increment
// taken from its definition dxi = sqrt(1/2 de_p : de_p), de_p the deviatoric plastic strain. Nothing of the
// code under test is used: the flow direction r = dg/dsigma is a central difference of g, the unknowns
// (sigma_1..3, dlambda) are found by Newton's method on the full residual
//   sigma - sigma_tr + dlambda D r(sigma, m) = 0,   f(sigma, m) = 0,   m = m(xi_n + dxi(dlambda r))
// with a finite-difference Jacobian. When that system has no admissible solution (Newton does not
// converge, or ends with dlambda < 0 or a deviator pointing against the trial's), the classical apex
// return: sigma = the apex (J2 = 0, I1 = k / alpha), the whole trial deviator plastic.
#include <array>
#include <cmath>

namespace dpref {

struct Law {
  double K, G, alpha, k, m0, h, d0;
};

inline Law law(double E, double nu, double phiDeg, double c, double m0, double h, double d0) {
  const double phi = phiDeg * M_PI / 180, den = std::sqrt(3.0) * (3 - std::sin(phi));
  return {E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu)), 2 * std::sin(phi) / den, 6 * c * std::cos(phi) / den, m0, h, d0};
}

using V3 = std::array<double, 3>;

inline double sqrtJ2(const V3& s) {
  const double p = (s[0] + s[1] + s[2]) / 3;
  double j2 = 0;
  for (double v : s) j2 += 0.5 * (v - p) * (v - p);
  return std::sqrt(j2);
}

struct Reference {
  Law L;
  V3 sig{0, 0, 0};
  double xi = 0;
  bool apex = false;  // the last step returned to the apex
  double hard(double x) const { return L.m0 + L.h * (1 - L.m0) * x / (1 - L.m0 + L.h * x); }
  double f(const V3& s, double m) const { return sqrtJ2(s) + m * L.alpha * (s[0] + s[1] + s[2]) - m * L.k; }
  double g(const V3& s, double m) const { return sqrtJ2(s) + m * L.d0 * L.alpha * (s[0] + s[1] + s[2]) - m * L.k; }
  // Central differences with the step 1e-4 J: truncation (1e-4)^2 relative (J is the curvature scale of g);
  // round-off 1e-16 |g's terms| / step stays below 1e-8 relative down to J ~ 1e-4 of the mean stress.
  V3 flow(const V3& s, double m) const {
    const double d = 1e-4 * sqrtJ2(s) + 1e-9;
    V3 r;
    for (int a = 0; a < 3; ++a) {
      V3 p = s, q = s;
      p[a] += d, q[a] -= d;
      r[a] = (g(p, m) - g(q, m)) / (2 * d);
    }
    return r;
  }
  double dxi(const V3& dep) const {  // sqrt(1/2 e:e), e the deviator of the plastic strain increment
    const double t = (dep[0] + dep[1] + dep[2]) / 3;
    double e2 = 0;
    for (double v : dep) e2 += (v - t) * (v - t);
    return std::sqrt(0.5 * e2);
  }
  V3 hooke(const V3& e) const {
    const double t = e[0] + e[1] + e[2];
    V3 s;
    for (int a = 0; a < 3; ++a) s[a] = L.K * t + 2 * L.G * (e[a] - t / 3);
    return s;
  }
  // Residual in scaled unknowns x = (sigma / S, dlambda G / S).
  std::array<double, 4> residual(const V3& tr, const std::array<double, 4>& x, double S) const {
    const V3 s{x[0] * S, x[1] * S, x[2] * S};
    const double dl = x[3] * S / L.G;
    V3 r0 = flow(s, 1.0);  // r at m = 1 only to get dxi's direction: the deviator of r does not depend on m
    const double m = hard(xi + dl * dxi(r0));
    const V3 r = flow(s, m), Dr = hooke(r);
    std::array<double, 4> R;
    for (int a = 0; a < 3; ++a) R[a] = (s[a] - tr[a] + dl * Dr[a]) / S;
    R[3] = f(s, m) / S;
    return R;
  }
  // One step with the principal strain increment de (fixed axes).
  void step(const V3& de) {
    const V3 dsig = hooke(de);
    V3 tr;
    for (int a = 0; a < 3; ++a) tr[a] = sig[a] + dsig[a];
    apex = false;
    const double S = sqrtJ2(tr) + std::fabs(tr[0] + tr[1] + tr[2]) + L.k;
    if (f(tr, hard(xi)) <= 1e-14 * S) { sig = tr; return; }
    std::array<double, 4> x{tr[0] / S, tr[1] / S, tr[2] / S, 0.0};
    bool ok = false;
    for (int it = 0; it < 60 && !ok; ++it) {
      const auto R = residual(tr, x, S);
      double J[4][5];
      for (int b = 0; b < 4; ++b) {  // forward-difference Jacobian
        auto y = x;
        y[b] += 1e-8;
        const auto Rb = residual(tr, y, S);
        for (int a = 0; a < 4; ++a) J[a][b] = (Rb[a] - R[a]) / 1e-8;
      }
      for (int a = 0; a < 4; ++a) J[a][4] = -R[a];
      for (int c = 0; c < 4; ++c) {  // Gauss elimination with partial pivoting
        int p = c;
        for (int a = c + 1; a < 4; ++a) if (std::fabs(J[a][c]) > std::fabs(J[p][c])) p = a;
        for (int b = 0; b < 5; ++b) std::swap(J[c][b], J[p][b]);
        for (int a = c + 1; a < 4; ++a) {
          const double q = J[a][c] / J[c][c];
          for (int b = c; b < 5; ++b) J[a][b] -= q * J[c][b];
        }
      }
      std::array<double, 4> dx;
      for (int a = 3; a >= 0; --a) {
        double v = J[a][4];
        for (int b = a + 1; b < 4; ++b) v -= J[a][b] * dx[b];
        dx[a] = v / J[a][a];
      }
      // Backtracking: halve the step while it does not reduce max |R| (near the apex the full Newton step
      // overshoots through J = 0, where g is not differentiable).
      auto norm = [](const std::array<double, 4>& v) {
        double m = 0;
        for (double a : v) m = std::max(m, std::fabs(a));
        return m;
      };
      double r = norm(R), lambda = 1;
      for (int cut = 0; cut < 40; ++cut, lambda *= 0.5) {
        auto y = x;
        for (int a = 0; a < 4; ++a) y[a] += lambda * dx[a];
        if (norm(residual(tr, y, S)) < r || r < 1e-11) break;
      }
      double n = 0;
      for (int a = 0; a < 4; ++a) x[a] += lambda * dx[a], n = std::max(n, std::fabs(lambda * dx[a]));
      // Converged when the step is below 1e-11 of the scale S and the residual before it below 1e-8: the
      // residual's own noise, the flow's 1e-8 error times dlambda D / S, reaches 1e-10 near the apex. 1e-8 S
      // is 1e-3 Pa here, far below the tests' bounds.
      ok = n < 1e-11 && r < 1e-8 && std::isfinite(n);
    }
    const V3 s{x[0] * S, x[1] * S, x[2] * S};
    const double pt = (tr[0] + tr[1] + tr[2]) / 3, ps = (s[0] + s[1] + s[2]) / 3;
    double align = 0;
    for (int a = 0; a < 3; ++a) align += (s[a] - ps) * (tr[a] - pt);
    if (ok && x[3] >= 0 && align >= 0 && sqrtJ2(s) > 1e-9 * S) {
      const double dl = x[3] * S / L.G;
      xi += dl * dxi(flow(s, 1.0));
      sig = s;
      return;
    }
    // Apex: the plastic strain is D^-1 (sigma_tr - apex); its deviator is that of the trial stress / 2G.
    apex = true;
    V3 devTr;
    for (int a = 0; a < 3; ++a) devTr[a] = (tr[a] - pt) / (2 * L.G);
    xi += dxi(devTr);
    const double pa = L.k / (3 * L.alpha);
    sig = {pa, pa, pa};
  }
  double vm() const { return std::sqrt(3.0) * sqrtJ2(sig); }
  double mean() const { return (sig[0] + sig[1] + sig[2]) / 3; }
};

}  // namespace dpref
