#pragma once
// Constants of the linear ordinary state-based solid in 3D, plane stress and plane strain, written so
// that one kernel serves all three (Pirzadeh et al. 2024 Eqs. 3, 4, 9-13; Mousavi et al. 2021 for 2D):
//   theta = k (D/m) sum omega x (e - e^dp) V'          (dilatation, Eq. 4/16)
//   e^d   = e - c theta x                               (deviatoric extension, Eq. 3)
//   t     = A theta omega x / m + B omega e^d / m       (scalar force state, Eqs. 9-13)
// 3D: D=3, k=1, c=1/3, A=3 kappa, B=15 mu. 2D: D=2, A=2 kappa, B=8 mu, and
//   plane stress: k=(1-2nu)/(1-nu), c=1/3+kappa/(8 mu);  plane strain: k=1, c=5/12.
// Check: for a homogeneous in-plane strain of an interior point these give sigma_mean = E/(2(1-nu)) tr
// (plane stress) and (kappa + mu/3) tr (plane strain) and sigma_dev = 2 mu dev, i.e. classical
// elasticity; the unit tests verify it on a lattice.
#include "core/Dimension.hpp"
#include "core/ElasticModuli.hpp"

namespace pf {

struct OsbConstants {
  double D, k, c, A, B;
  // yield-surface constants in terms of the continuum weighted volume (Eqs. 36, 39, 46):
  // 3D: m = 4 pi delta^5 / 5;  2D: m = pi h delta^4 / 2.
};

inline OsbConstants osbConstants(Dimension dim, const ElasticModuli& em) {
  const double kappa = em.bulk, mu = em.shear, nu = em.poisson;
  switch (dim) {
    case Dimension::ThreeD: return {3.0, 1.0, 1.0 / 3.0, 3.0 * kappa, 15.0 * mu};
    case Dimension::PlaneStress:
      return {2.0, (1.0 - 2.0 * nu) / (1.0 - nu), 1.0 / 3.0 + kappa / (8.0 * mu), 2.0 * kappa, 8.0 * mu};
    case Dimension::PlaneStrain: return {2.0, 1.0, 5.0 / 12.0, 2.0 * kappa, 8.0 * mu};
  }
  return {};
}

}  // namespace pf
