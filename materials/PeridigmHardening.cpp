#include "PeridigmHardening.hpp"

#include <cfloat>
#include <cmath>

namespace pf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// g(dl) of the consistency condition (header), in u = alpha dl.
struct Consistency {
  double S2, psiN, Ha;  // |t^d_tr|^2 / 2, psi0 + H lambdaN, H / alpha
  double g(double u) const { return S2 / ((1 + u) * (1 + u)) - psiN - Ha * u; }
  double dg(double u) const { return -2.0 * S2 / ((1 + u) * (1 + u) * (1 + u)) - Ha; }
};

// g is convex and decreasing with g(0) > 0: Newton from u = 0 rises monotonically to the root.
double newtonRoot(const Consistency& c) {
  double u = 0.0;
  for (int it = 0; it < 200; ++it) {
    const double du = -c.g(u) / c.dg(u);
    u += du;
    if (!(std::fabs(du) > 1e-15 * (1.0 + u))) break;
  }
  return u;
}

}  // namespace

double peridigmCubicRoot(double tdNorm, double lambdaN, double psi0, double alpha, double H) {
  // Peridigm's coefficients: (1/alpha + dl)^2 (psi0/H + lambdaN + dl) = tdNorm^2 / (2 alpha^2 H).
  const double a = 2. / alpha + lambdaN + psi0 / H;
  const double b = (H + 2. * alpha * H * lambdaN + 2. * alpha * psi0) / (alpha * alpha * H);
  const double c = (2. * H * lambdaN + 2. * psi0 - tdNorm * tdNorm) / (2. * alpha * alpha * H);
  const double Q = (a * a - 3. * b) / 9.;
  const double R = (2. * a * a * a - 9. * a * b + 27. * c) / 54.;
  if (R * R < Q * Q * Q) {  // three real roots: the smallest positive one
    const double theta = std::acos(R / std::sqrt(Q * Q * Q));
    const double roots[3] = {-2. * std::sqrt(Q) * std::cos(theta / 3.) - a / 3.,
                             -2. * std::sqrt(Q) * std::cos(theta / 3. + 2. * kPi / 3.) - a / 3.,
                             -2. * std::sqrt(Q) * std::cos(theta / 3. - 2. * kPi / 3.) - a / 3.};
    double min = DBL_MAX;
    for (double r : roots)
      if (r > 0.0 && std::fabs(r) < std::fabs(min)) min = r;
    return min == DBL_MAX ? 0.0 : min;
  }
  // One real root (Cardano). A = 0 only with Q = 0, where Peridigm divides by it.
  const double sgnR = R > 0.0 ? 1.0 : (R < 0.0 ? -1.0 : 0.0);
  const double A = -sgnR * std::pow(std::fabs(R) + std::sqrt(R * R - Q * Q * Q), 1. / 3.);
  const double val = (A + (A != 0.0 ? Q / A : 0.0)) - a / 3.;
  return val < 0.0 ? 0.0 : val;
}

double peridigmDeltaLambda(double tdNorm, double lambdaN, double psi0, double alpha, double H) {
  if (!(tdNorm * tdNorm / 2 - psi0 > 0.0)) return 0.0;  // Peridigm's trigger: the initial yield surface
  if (H == 0.0) {
    const double dl = (tdNorm / std::sqrt(2.0 * psi0) - 1.0) / alpha;
    return dl > 0.0 ? dl : 0.0;
  }
  const Consistency c{0.5 * tdNorm * tdNorm, psi0 + H * lambdaN, H / alpha};
  if (!(c.g(0.0) > 0.0)) return 0.0;  // inside the hardened surface: no positive root (Peridigm's 0)
  const double dl = peridigmCubicRoot(tdNorm, lambdaN, psi0, alpha, H);
  if (std::fabs(c.g(alpha * dl)) <= 1e-10 * c.S2) return dl;  // Peridigm's root (or 0 inside the surface)
  return newtonRoot(c) / alpha;
}

}  // namespace pf
