#include "FosterViscoplasticity.hpp"

#include <cmath>
#include <cstdio>

#include "core/Material.hpp"

namespace pf {

double fosterFlowStress(const FosterLaw& law, double epsP, double rate) {
  return law.yield * std::pow(1.0 + epsP / law.eps0, 1.0 / law.n) * std::pow(1.0 + rate / law.rate0, 1.0 / law.m);
}

FosterStep fosterUpdate(const FosterLaw& law, double K, double mu, const Mat3& tauN, double epsPn, const Mat3& de,
                        double dt) {
  const double r23 = std::sqrt(2.0 / 3.0);
  const double p = trace(tauN) / 3.0 + K * trace(de);           // Eq. 52
  const Mat3 Str = deviator(tauN) + (2.0 * mu) * deviator(de);  // Eq. 49
  const double sTr = std::sqrt(ddot(Str, Str));
  const double g = fosterFlowStress(law, epsPn, 0.0);           // Eq. 59 at the step's start (Eq. 37)
  FosterStep out{Str, epsPn, 0.0, 0};
  out.tau[0] += p, out.tau[4] += p, out.tau[8] += p;
  if (sTr <= r23 * g || !(dt > 0.0)) return out;                // elastic (Eq. 50, first case)
  // Eq. 60 as the radial return: phi(x) = |S_tr| - 2 mu x - sqrt(2/3) G(x) = 0, x = dlambda. phi is
  // decreasing, phi(0) > 0 and phi(|S_tr|/(2 mu)) < 0: Newton, with bisection whenever it leaves the bracket.
  const double c = r23 / (dt * law.rate0);
  auto phi = [&](double x, double* dphi) {
    const double base = 1.0 + c * x;
    const double G = g * std::pow(base, 1.0 / law.m);
    *dphi = -2.0 * mu - r23 * G * c / (law.m * base);
    return sTr - 2.0 * mu * x - r23 * G;
  };
  double lo = 0.0, hi = sTr / (2.0 * mu);
  double x = (sTr - r23 * g) / (2.0 * mu);  // the rate-independent return: phi(x) <= 0, so x >= root
  hi = std::min(hi, x);
  const double tol = 1e-15 * hi + 1e-300;
  for (int it = 1; it <= 100; ++it) {
    double d;
    const double f = phi(x, &d);
    if (f > 0) lo = x; else hi = x;
    double next = x - f / d;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - x) <= tol || hi - lo <= tol) {
      const double G = g * std::pow(1.0 + c * next, 1.0 / law.m);
      out.tau = (r23 * G / sTr) * Str;  // Eq. 50, second case
      out.tau[0] += p, out.tau[4] += p, out.tau[8] += p;
      out.epsP = epsPn + r23 * next;
      out.rate = r23 * next / dt;
      out.iterations = it;
      return out;
    }
    x = next;
  }
  char msg[200];
  std::snprintf(msg, sizeof msg, "Viscoplastic Correspondence: the return mapping did not converge in 100 iterations "
                "(|S_trial| = %.6g, dt = %.3g)", sTr, dt);
  throw ConstitutiveFailure(msg);
}

}  // namespace pf
