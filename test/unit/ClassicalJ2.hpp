#pragma once
// Independent classical small-strain J2 return mapping with linear isotropic (K) and kinematic (H)
// hardening (Simo & Hughes 1998, Box 3.1/3.2), for verifying the peridynamic model. Plane stress by
// iterating the out-of-plane strain until sigma_zz = 0; plane strain by eps_zz = 0.
#include <array>
#include <cmath>
#include <stdexcept>

namespace pftest {

using Sym = std::array<double, 9>;  // row-major 3x3

struct ClassicalJ2 {
  enum class Mode { ThreeD, PlaneStress, PlaneStrain };
  double kappa, mu, sy, K, H;
  Mode mode;
  // committed state
  Sym ep{}, beta{};
  double alpha = 0.0, ezz = 0.0;
  // trial state
  Sym epT{}, betaT{}, sigma{};
  double alphaT = 0.0, ezzT = 0.0;

  ClassicalJ2(double E, double nu, double sy_, double K_, double H_, Mode m)
      : kappa(E / (3 * (1 - 2 * nu))), mu(E / (2 * (1 + nu))), sy(sy_), K(K_), H(H_), mode(m) {}

  // Box 3.2 from the committed state, total strain eps (3D).
  void radialReturn(const Sym& eps) {
    const double tr = eps[0] + eps[4] + eps[8];
    Sym xi{};
    for (int a = 0; a < 9; ++a) {
      const double dev = eps[a] - (a % 4 == 0 ? tr / 3 : 0.0);
      xi[a] = 2 * mu * (dev - ep[a]) - beta[a];
    }
    double nxi = 0;
    for (double v : xi) nxi += v * v;
    nxi = std::sqrt(nxi);
    const double f = nxi - std::sqrt(2.0 / 3.0) * (sy + K * alpha);
    double dg = 0.0;
    if (f > 0) dg = f / (2 * mu + 2.0 / 3.0 * (K + H));
    alphaT = alpha + std::sqrt(2.0 / 3.0) * dg;
    for (int a = 0; a < 9; ++a) {
      const double n = nxi > 0 ? xi[a] / nxi : 0.0;
      epT[a] = ep[a] + dg * n;
      betaT[a] = beta[a] + 2.0 / 3.0 * H * dg * n;
      const double dev = eps[a] - (a % 4 == 0 ? tr / 3 : 0.0);
      sigma[a] = 2 * mu * (dev - epT[a]) + (a % 4 == 0 ? kappa * tr : 0.0);
    }
  }

  // In-plane (or 3D) strain eps; for PlaneStress eps[8] is solved for.
  void update(Sym eps) {
    if (mode == Mode::PlaneStrain) eps[8] = 0.0;
    if (mode != Mode::PlaneStress) { radialReturn(eps); return; }
    // secant on eps_zz, starting from the committed value and an elastic predictor
    double z0 = ezz;
    eps[8] = z0; radialReturn(eps);
    double s0 = sigma[8];
    double z1 = z0 - s0 / (kappa + 4.0 * mu / 3.0);
    for (int it = 0; it < 100; ++it) {
      eps[8] = z1; radialReturn(eps);
      const double s1 = sigma[8];
      if (std::fabs(s1) < 1e-12 * sy) { ezzT = z1; return; }
      const double z2 = s1 == s0 ? z1 : z1 - s1 * (z1 - z0) / (s1 - s0);
      z0 = z1; s0 = s1; z1 = z2;
    }
    throw std::runtime_error("classical plane stress: sigma_zz iteration did not converge");
  }

  void commit() { ep = epT; beta = betaT; alpha = alphaT; ezz = ezzT; }

  double vonMises() const {
    const double tr = sigma[0] + sigma[4] + sigma[8];
    double s2 = 0;
    for (int a = 0; a < 9; ++a) {
      const double d = sigma[a] - (a % 4 == 0 ? tr / 3 : 0.0);
      s2 += d * d;
    }
    return std::sqrt(1.5 * s2);
  }
};

// Second, independent plane-stress reference: the projected plane-stress return mapping of Simo & Taylor
// (Simo & Hughes 1998, §3.4 / Box 3.3), a scalar equation in the consistency parameter dg instead of an
// outer iteration on eps_zz. Voigt in-plane vectors (s11, s22, s12), strain (e11, e22, 2 e12); P =
// [[2,-1,0],[-1,2,0],[0,0,6]]/3 so that s.P.s = |dev s|^2 with s_zz = 0. The in-plane elastic tensor is
// given by its three eigenvalues, which it shares with P whenever it has square (cubic) symmetry:
// ca on (1,1,0)/sqrt2 (isotropic: E/(1-nu)), cb on (1,-1,0)/sqrt2 (2 mu), cs on the engineering shear
// (mu) -- so the same code runs with the isotropic moduli or with a lattice point's own discrete moduli.
// Two kinematic models:
//   Tensor : classical linear kinematic hardening (the reference), back stress tensor b stored as a plane
//            tensor (b_zz = 0 after a shift by b_zz I, which leaves dev b unchanged), db = 2/3 H dg xi,
//            flow along xi = s - b. Agrees with ClassicalJ2 (eps_zz iteration) to round-off (tested).
//   Scalar : the classical counterpart of the peridynamic model's scalar back stress (Pirzadeh et al.
//            Eqs. 39/45/46/56): flow along s (the back stress does not enter the flow direction), yield
//            |sgn sigma_vm - q| = sigma_y + K alpha, q += dir H d(alpha), dir = sign(sgn sigma_vm - q).
//            sgn = sign(s11 + s22), the PD sign rule in 2D: sign(sum (t^d)^3 V) is the sign of tr Q (the
//            circle integral of (n.Q.n)^3 is tr Q (5a^2 - 2ab + 5b^2)/16, a, b the eigenvalues of Q) and
//            tr Q ~ -s_zz = (s11 + s22)/3 in plane stress; kept when it vanishes. (sign(J3) instead is
//            36 % of sigma_y off on the cyclic path: J3 = s11 s22 s_zz passes through 0 as s22 -> 0.)
//            Identical to Tensor on proportional stress paths and for H = 0.
struct PlaneStressJ2 {
  enum class Kinematic { Tensor, Scalar };
  double lam[3];  // eigenvalues of C P: ca/3, cb, 2 cs
  double ca, cb, cs, sy, K, H;
  Kinematic kin;
  // committed state (eigen basis of C and P: u1 = (x11 + x22)/sqrt2, u2 = (x11 - x22)/sqrt2, u3 = x12;
  // plastic strain in engineering components)
  double ep[3] = {0, 0, 0}, b[3] = {0, 0, 0}, alpha = 0, q = 0, sgn = 1;
  double epT[3] = {0, 0, 0}, bT[3] = {0, 0, 0}, alphaT = 0, qT = 0, sgnT = 1;
  double s[3] = {0, 0, 0};  // stress, eigen basis
  double dgLast = 0;

  PlaneStressJ2(double ca_, double cb_, double cs_, double sy_, double K_, double H_, Kinematic k)
      : ca(ca_), cb(cb_), cs(cs_), sy(sy_), K(K_), H(H_), kin(k) {
    lam[0] = ca / 3; lam[1] = cb; lam[2] = 2 * cs;
  }
  static PlaneStressJ2 isotropic(double E, double nu, double sy, double K, double H, Kinematic k) {
    return PlaneStressJ2(E / (1 - nu), E / (1 + nu), E / (2 * (1 + nu)), sy, K, H, k);
  }
  static double pnorm2(const double* x) { return x[0] * x[0] / 3 + x[1] * x[1] + 2 * x[2] * x[2]; }
  static constexpr double kR2 = 1.4142135623730951;

  // Strain eps (row-major 3x3, in-plane part used).
  void update(const std::array<double, 9>& eps) {
    const double e[3] = {(eps[0] + eps[4]) / kR2, (eps[0] - eps[4]) / kR2, 2 * eps[1]};  // engineering shear
    double tr[3];
    const double c[3] = {ca, cb, cs};
    for (int i = 0; i < 3; ++i) tr[i] = c[i] * (e[i] - ep[i]);
    for (int i = 0; i < 3; ++i) { epT[i] = ep[i]; bT[i] = b[i]; s[i] = tr[i]; }
    alphaT = alpha; qT = q; sgnT = sgn; dgLast = 0;
    if (kin == Kinematic::Tensor) {
      double xt[3];
      for (int i = 0; i < 3; ++i) xt[i] = tr[i] - b[i];
      auto xi = [&](double dg, double* x) {
        for (int i = 0; i < 3; ++i) x[i] = xt[i] / (1 + 2.0 / 3.0 * H * dg + dg * lam[i]);
      };
      auto f = [&](double dg) {
        double x[3]; xi(dg, x);
        const double n = std::sqrt(pnorm2(x));
        return n - std::sqrt(2.0 / 3.0) * (sy + K * (alpha + std::sqrt(2.0 / 3.0) * dg * n));
      };
      if (f(0) <= 0) return;
      const double dg = solve(f);
      double x[3]; xi(dg, x);
      const double Px[3] = {x[0] / 3, x[1], 2 * x[2]};
      for (int i = 0; i < 3; ++i) {
        epT[i] = ep[i] + dg * Px[i];
        bT[i] = b[i] + 2.0 / 3.0 * H * dg * x[i];
        s[i] = tr[i] - dg * c[i] * Px[i];
      }
      alphaT = alpha + std::sqrt(2.0 / 3.0) * dg * std::sqrt(pnorm2(x));
      dgLast = dg;
      return;
    }
    // Scalar back stress.
    const double vmTr = std::sqrt(1.5 * pnorm2(tr));
    if (tr[0] > 1e-8 * vmTr) sgnT = 1; else if (tr[0] < -1e-8 * vmTr) sgnT = -1;  // u1 = (s11 + s22)/sqrt2
    const double dir = sgnT * vmTr - q >= 0 ? 1.0 : -1.0;
    const double sbar = sy + K * alpha + dir * q;
    auto vmAt = [&](double dg) {
      double x[3];
      for (int i = 0; i < 3; ++i) x[i] = tr[i] / (1 + dg * lam[i]);
      return std::sqrt(1.5 * pnorm2(x));
    };
    auto g = [&](double dg) { const double v = vmAt(dg); return v - sbar - (K + H) * 2.0 / 3.0 * dg * v; };
    if (g(0) <= 0) return;
    const double dg = solve(g);
    double x[3];
    for (int i = 0; i < 3; ++i) x[i] = tr[i] / (1 + dg * lam[i]);
    const double Px[3] = {x[0] / 3, x[1], 2 * x[2]};
    const double dalpha = 2.0 / 3.0 * dg * std::sqrt(1.5 * pnorm2(x));
    for (int i = 0; i < 3; ++i) { epT[i] = ep[i] + dg * Px[i]; s[i] = x[i]; }
    alphaT = alpha + dalpha;
    qT = q + dir * H * dalpha;
    dgLast = dg;
  }

  // Root of a decreasing function with f(0) > 0: bracket, then bisection to round-off.
  template <class Fn> static double solve(Fn f) {
    double lo = 0, hi = 1e-12;
    while (f(hi) > 0) { lo = hi; hi *= 2; }
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  // Cartesian in-plane stress (s11, s22, s12) of an eigen-basis vector.
  static void cart(const double* u, double* x) { x[0] = (u[0] + u[1]) / kR2; x[1] = (u[0] - u[1]) / kR2; x[2] = u[2]; }
  double vonMises() const { return std::sqrt(1.5 * pnorm2(s)); }
  std::array<double, 3> stress() const { std::array<double, 3> x; cart(s, x.data()); return x; }
  void commit() {
    for (int i = 0; i < 3; ++i) { ep[i] = epT[i]; b[i] = bT[i]; }
    alpha = alphaT; q = qT; sgn = sgnT;
  }
};

}  // namespace pftest
