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

}  // namespace pftest
