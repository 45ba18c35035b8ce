#include "PeridigmJ2Update.hpp"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {

// The elastic trial of the increment, split as Peridigm's kernels use it.
struct Trial {
  Mat3 devDe;    // dev(de)
  Mat3 tau;      // tau_tr
  Mat3 s;        // dev(tau_tr)
  double p;      // tr(tau_tr)/3
  double norm;   // |s_tr|
  double vm;     // sqrt(3/2) |s_tr|
};

Trial trial(const Mat3& tauN, const Mat3& de, double K, double G) {
  Trial t;
  t.devDe = deviator(de);
  const double dil = trace(de);
  t.tau = tauN + (2.0 * G) * t.devDe;
  t.tau[0] += K * dil, t.tau[4] += K * dil, t.tau[8] += K * dil;
  t.p = trace(t.tau) / 3.0;
  t.s = deviator(t.tau);
  const double ss = ddot(t.s, t.s);
  t.norm = std::sqrt(ss);
  t.vm = std::sqrt(1.5 * ss);
  return t;
}

// The return onto sqrt(3/2)|s| = yf and Peridigm's generic eqps increment (see the header).
PeridigmJ2Step plasticReturn(const Trial& t, const Mat3& tauN, double eqpsN, double G, double yf) {
  const double normTr = std::max(1.0e-20, t.norm);
  const Mat3 s = (std::sqrt(2.0 / 3.0) * yf / normTr) * t.s;
  PeridigmJ2Step r;
  r.tau = s;
  r.tau[0] += t.p, r.tau[4] += t.p, r.tau[8] += t.p;
  const Mat3 sN = deviator(tauN);
  const double normN = std::max(1.0e-20, std::sqrt(ddot(sN, sN)));
  const Mat3 plastic = t.devDe - (0.5 / G) * (s - sN);
  const Mat3 direction = 0.5 * ((1.0 / normTr) * s + (1.0 / normN) * sN);
  r.eqps = eqpsN + std::max(0.0, std::sqrt(2.0 / 3.0) * ddot(plastic, direction));
  return r;
}

}  // namespace

PeridigmJ2Step peridigmPerfectPlastic(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G, double Y) {
  const Trial t = trial(tauN, de, K, G);
  if (t.vm > Y) return plasticReturn(t, tauN, eqpsN, G, Y);
  return {t.tau, eqpsN};
}

PeridigmJ2Step peridigmIsotropicHardening(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G,
                                          double Y, double H) {
  const Trial t = trial(tauN, de, K, G);
  if (t.vm < Y) return {t.tau, eqpsN};
  const Mat3 sN = deviator(tauN);
  const double along = ddot(t.s, t.devDe) / std::max(1.0e-20, t.norm);
  const double dl = (6.0 * along * G + 3.0 * std::sqrt(ddot(sN, sN)) - std::sqrt(6.0) * Y) / (2.0 * (H + 3.0 * G));
  const double yf = Y + H * (eqpsN + std::sqrt(2.0 / 3.0) * dl);
  if (t.vm > yf) return plasticReturn(t, tauN, eqpsN, G, yf);
  return {t.tau, eqpsN};
}

double NeedlemanLaw::flowStress(double Y, double dl, double eps, double dt) const {
  const double hardening = Y * std::pow(1.0 + eps / e0, n) / (1.0 + std::pow(eps / e1, 2.0));
  return hardening * std::pow(std::sqrt(2.0 / 3.0) * dl / dt / rate0, m);
}

namespace {

// Peridigm's bisection for the Needleman multiplier (see the header), with its iteration bound.
double needlemanMultiplier(const NeedlemanLaw& law, double Y, double eqpsN, double along, double normN, double G,
                           double dt) {
  auto residual = [&](double dl) {
    return along - dl - 1.0 / 2.0 / G * (std::sqrt(2.0 / 3.0) * law.flowStress(Y, dl, eqpsN + dl, dt) - normN);
  };
  double a = 0.0, b = 1.0, c = 0.5;
  for (int iter = 0; iter < 100000; ++iter) {
    const double fb = residual(b), fc = residual(c);
    // Peridigm's test: the same sign at b and c moves b, otherwise a.
    if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0))
      b = c;
    else
      a = c;
    const double previous = c;
    c = (a + b) / 2.0;
    if (std::fabs(c - previous) / std::fabs(c) < 1.0e-6) break;
  }
  return c;
}

}  // namespace

PeridigmJ2Step peridigmNeedleman(const Mat3& tauN, const Mat3& de, double eqpsN, double K, double G, double Y,
                                 const NeedlemanLaw& law, double dt) {
  const Trial t = trial(tauN, de, K, G);
  if (t.vm < Y || dt <= 0.0) return {t.tau, eqpsN};
  const Mat3 sN = deviator(tauN);
  const double along = ddot(t.s, t.devDe) / std::max(1.0e-20, t.norm);
  const double dl = needlemanMultiplier(law, Y, eqpsN, along, std::sqrt(ddot(sN, sN)), G, dt);
  const double yf = law.flowStress(Y, dl, eqpsN + std::sqrt(2.0 / 3.0) * dl, dt);
  if (t.vm > yf) return plasticReturn(t, tauN, eqpsN, G, yf);
  return {t.tau, eqpsN};
}

}  // namespace pf
