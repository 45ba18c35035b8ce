#pragma once
// Hooke's law on the unrotated Cauchy stress of the correspondence models (isotropic, bulk K, shear mu): the
// increment of a strain increment, its inverse, and the stored energy density. Plain functions on tensors.
#include "core/Tensor3.hpp"

namespace pf {

// C : d = 2 mu dev(d) + K tr(d) I.
inline Mat3 hookeIncrement(double bulk, double shear, const Mat3& d) {
  Mat3 s = (2.0 * shear) * deviator(d);
  const double p = bulk * trace(d);
  s[0] += p, s[4] += p, s[8] += p;
  return s;
}

// C^-1 : dtau = tr(dtau)/(9 K) I + dev(dtau)/(2 mu).
inline Mat3 hookeStrain(double bulk, double shear, const Mat3& dtau) {
  Mat3 e = (1.0 / (2.0 * shear)) * deviator(dtau);
  const double v = trace(dtau) / (9.0 * bulk);
  e[0] += v, e[4] += v, e[8] += v;
  return e;
}

// 1/2 tau : C^-1 : tau = p^2 / (2 K) + s : s / (4 mu), p = tr(tau)/3, s = dev(tau).
inline double hookeEnergyDensity(double bulk, double shear, const Mat3& tau) {
  const double p = trace(tau) / 3.0;
  const Mat3 s = deviator(tau);
  return p * p / (2.0 * bulk) + ddot(s, s) / (4.0 * shear);
}

}  // namespace pf
