#pragma once
// Damage by stress (Li & Geng, seed 003, Sec. 5.2, Eqs. 49-51; `Damage Model` = `Maximum Principal Stress`):
// bond (i, j) breaks, for good, once t_bond = (sigma1_i + sigma1_j) / 2 exceeds the Tensile Strength f_t, with
// sigma1 the largest principal value of each end's Cauchy stress (Eq. 50); a broken bond's influence is 0 in
// every family sum (Eq. 49: omega' = 0); Damage = broken / total bonds of the point (Eq. 51). Only the pointwise
// rule lives here; the correspondence models apply it in their gather (materials/CorrespondenceMaterial.cpp).
#include <algorithm>
#include <cmath>

namespace pf {

// The largest eigenvalue of the symmetric tensor s = (xx, yy, zz, xy, yz, xz) by the closed-form trigonometric
// solution of the characteristic cubic (Smith 1961): with m = tr s / 3, p2 = |s - m I|^2 / 6 and
// q = det((s - m I) / sqrt(p2)) / 2, the eigenvalues are m + 2 sqrt(p2) cos(phi + 2 pi k / 3), phi = acos(q) / 3;
// the largest is k = 0. Rotation-invariant, so the unrotated stress R^T sigma R gives sigma's own sigma1.
inline double maxPrincipal(const double* s) {
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - m, b = s[1] - m, c = s[2] - m, d = s[3], e = s[4], f = s[5];
  const double p2 = (a * a + b * b + c * c + 2.0 * (d * d + e * e + f * f)) / 6.0;
  if (!(p2 > 0.0)) return m;  // isotropic (or not finite: then m carries the NaN)
  const double p = std::sqrt(p2);
  // det of the symmetric deviator, divided by p^3, halved.
  const double det = a * (b * c - e * e) - d * (d * c - e * f) + f * (d * e - b * f);
  const double q = std::max(-1.0, std::min(1.0, det / (2.0 * p2 * p)));
  return m + 2.0 * p * std::cos(std::acos(q) / 3.0);
}

// The rule for one bond: broken before (committed or base flag bn != 0) or, while breaks are allowed, the mean of
// its two ends' sigma1 above f_t (strictly: a stress equal to f_t does not break, Eq. 49). Symmetric in its ends
// bit for bit (a + b == b + a in floating point), so the bond's two half-bonds, on whichever ranks, agree.
inline bool bondBrokenByStress(double bn, double sigma1i, double sigma1j, double ft) {
  return bn != 0.0 || 0.5 * (sigma1i + sigma1j) > ft;
}

}  // namespace pf
