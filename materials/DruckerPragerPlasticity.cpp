#include "DruckerPragerPlasticity.hpp"

#include <cmath>
#include <cstdio>

#include "core/Material.hpp"

namespace pf {

DruckerPragerLaw druckerPragerLaw(double frictionDegrees, double cohesion, double m0, double h, double d0) {
  const double phi = frictionDegrees * 3.14159265358979323846 / 180.0;
  const double den = std::sqrt(3.0) * (3.0 - std::sin(phi));
  return {2.0 * std::sin(phi) / den, 6.0 * cohesion * std::cos(phi) / den, m0, h, d0};  // Eq. 38
}

double druckerPragerHardening(const DruckerPragerLaw& law, double xi) {
  const double den = 1.0 - law.m0 + law.h * xi;
  if (!(den > 0.0)) return law.m0;  // m0 = 1 with xi = 0 or h = 0: m stays 1 (the limit of A14)
  return law.m0 + law.h * (1.0 - law.m0) * xi / den;  // Eq. A14
}

void druckerPragerCubic(const DruckerPragerLaw& law, double K, double G, double iTrial, double jTrial, double xiN,
                        double b[4]) {
  const double A = law.A, k = law.B;
  // Eq. A17: m(dl) = (a11 + a12 dl) / (a13 + a14 dl) with xi = xiN + dl/2.
  const double a11 = law.m0 * (1.0 - law.m0) + law.h * xiN, a12 = 0.5 * law.h;
  const double a13 = 1.0 - law.m0 + law.h * xiN, a14 = a12;
  const double b11 = 9.0 * K * A * law.d0 * a12, b12 = 9.0 * K * A * law.d0 * a11 + iTrial * a14, b13 = iTrial * a13;
  // Eq. A16; B4's first term corrected to a13^2 J_trial (the expansion of (J_tr - G dl)(a13 + a14 dl)^2).
  b[0] = -a14 * a14 * G - A * a12 * b11;
  b[1] = -2.0 * a13 * a14 * G + a14 * a14 * jTrial - A * a11 * b11 - A * a12 * b12 - k * a12 * a14;
  b[2] = 2.0 * a13 * a14 * jTrial - a13 * a13 * G - A * a11 * b12 - A * a12 * b13 - k * a11 * a14 - k * a12 * a13;
  b[3] = a13 * a13 * jTrial - A * a11 * b13 - k * a11 * a13;
}

double druckerPragerYieldRatio(const DruckerPragerLaw& law, const Mat3& tau, double m) {
  const Mat3 s = deviator(tau);
  const double i1 = -trace(tau), j = std::sqrt(0.5 * ddot(s, s));  // compression positive I (sign convention above)
  const double scale = m * (law.A * std::fabs(i1) + law.B);
  if (!(scale > 0.0)) return j > 0.0 ? 1.0 : 0.0;
  return (j - m * (law.A * i1 + law.B)) / scale;
}

DruckerPragerStep druckerPragerUpdate(const DruckerPragerLaw& law, double K, double G, const Mat3& tauN, double xiN,
                                      const Mat3& de) {
  // Elastic predictor, Eqs. A1-A3, in the paper's compression-positive I and s.
  const Mat3 sTr = -1.0 * (deviator(tauN) + (2.0 * G) * deviator(de));
  const double iTr = -(trace(tauN) + 3.0 * K * trace(de));
  const double jTr = std::sqrt(0.5 * ddot(sTr, sTr));
  const double mN = druckerPragerHardening(law, xiN);
  DruckerPragerStep out{tauN + (2.0 * G) * deviator(de), xiN, mN, 0.0, false, 0};
  const double pTr = K * trace(de);
  out.tau[0] += pTr, out.tau[4] += pTr, out.tau[8] += pTr;
  const double scale = jTr + mN * (law.A * std::fabs(iTr) + law.B);
  if (jTr - mN * (law.A * iTr + law.B) <= 1e-14 * scale) return out;  // Eq. 41: elastic (round-off on f = 0 too)

  const double A = law.A, c9 = 9.0 * K * A * law.d0;
  // phi(dl): the consistency condition f_n+1 = 0 (Eqs. 45, A9, A10, A13, A14) and its derivative.
  auto phi = [&](double dl, double* dphi, double* m, double* iNew) {
    const double xi = xiN + 0.5 * dl;
    *m = druckerPragerHardening(law, xi);
    const double den = 1.0 - law.m0 + law.h * xi;
    const double dm = den > 0.0 ? 0.5 * law.h * (1.0 - law.m0) * (1.0 - law.m0) / (den * den) : 0.0;  // Eq. 46
    *iNew = iTr + c9 * (*m) * dl;                                                                     // Eq. A9
    *dphi = -G - dm * (A * (*iNew) + law.B) - (*m) * A * c9 * ((*m) + dm * dl);
    return jTr - G * dl - (*m) * (A * (*iNew) + law.B);                                              // A10 in f
  };
  double lo = 0.0, hi = jTr / G, d, m, iNew;
  // The cone return ends at J_n+1 = J_tr - G dl >= 0 (Eq. A10): if f is still positive at J = 0, i.e.
  // the return would pass the apex, map to the apex.
  if (!(phi(hi, &d, &m, &iNew) < 0.0)) {
    out.apex = true;
    out.dlambda = hi;
    out.xi = xiN + 0.5 * hi;  // Eq. 47: the deviatoric plastic strain is s_tr / (2 G), sqrt(1/2 |.|^2) = J_tr / (2 G)
    out.m = druckerPragerHardening(law, out.xi);
    const double pApex = A > 0.0 ? law.B / (3.0 * A) : -iTr / 3.0;  // tension positive; A = 0: no apex, J -> 0
    out.tau = Mat3{pApex, 0, 0, 0, pApex, 0, 0, 0, pApex};
    return out;
  }
  double dl = 0.0;
  const double tol = 1e-15 * hi;
  for (int it = 1; it <= 100; ++it) {
    const double f = phi(dl, &d, &m, &iNew);
    if (f > 0.0) lo = dl; else hi = dl;
    double next = dl;  // f = 0 exactly (h = 0 makes f linear in dl): done, and dl is the bracket's end
    if (f != 0.0) {
      next = dl - f / d;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    }
    if (std::fabs(next - dl) <= tol || hi - lo <= tol) {
      dl = next;
      phi(dl, &d, &m, &iNew);
      const double jNew = jTr - G * dl;                // Eq. A10
      out.tau = (-jNew / jTr) * sTr;                   // Eq. A12, back to tension positive
      const double p = -iNew / 3.0;                    // Eq. A18
      out.tau[0] += p, out.tau[4] += p, out.tau[8] += p;
      out.xi = xiN + 0.5 * dl;                         // Eq. A13
      out.m = m;                                       // Eq. A14
      out.dlambda = dl;
      out.iterations = it;
      return out;
    }
    dl = next;
  }
  char msg[200];
  std::snprintf(msg, sizeof msg, "Drucker Prager Correspondence: the return mapping did not converge in 100 iterations "
                "(J_trial = %.6g, I_trial = %.6g)", jTr, iTr);
  throw ConstitutiveFailure(msg);
}

}  // namespace pf
