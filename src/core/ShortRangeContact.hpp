#pragma once
// Peridigm's short-range contact force (Peridigm_ShortRangeForceContactModel.cpp): two points closer than the
// contact radius r_c in the deformed configuration push each other apart, with Coulomb friction against their
// relative tangential velocity. Peridigm evaluates a pair from both ends, each end with its own block's horizon,
// and adds both halves to both points; this gives the sum of the two halves for one point, so that a point's force
// is summed in one place (its owner) in a fixed partner order.
namespace pf {

struct ShortRangeForceLaw {
  double contactRadius = 0.0;   // r_c: pairs closer than this interact
  double springConstant = 0.0;  // k (a modulus; Peridigm's decks use about 15 times the bulk modulus)
};

// The pair's data seen from point i: positions y and velocities v of i and of its partner j, j's volume, and the
// horizons of the blocks of i and j.
struct ContactPair {
  const double *yi, *yj, *vi, *vj;
  double volumeJ, horizonI, horizonJ;
};

// Adds to fi (3 values) the force density on i from j and returns true when |y_j - y_i| < r_c (else adds nothing):
//   normal   (c(h_i) + c(h_j)) (r_c - d) V_j (y_i - y_j) / d,       c(h) = 9 k / (pi h^5),
//   friction -mu (c(h_i) + c(h_j)) (r_c - d) V_j w / |w|,          w = (v_i,t - v_j,t) / 2,
// v_t the velocity less its component along y_j - y_i (no friction where w = 0 or mu = 0). Peridigm's c is
// 9 k / (pi h^4) per end, "half of 18" as each end adds to both points, times (r_c - d) / h.
bool addShortRangeForce(const ShortRangeForceLaw& law, double friction, const ContactPair& p, double* fi);

// i's half of the energy the pair's normal spring stores, (1/4) (c(h_i) + c(h_j)) V_i V_j (r_c - d)^2 (0 when
// d >= r_c): the normal force on i, (c(h_i) + c(h_j)) V_i V_j (r_c - d), is minus its derivative in d, and the
// pair's other half is j's. Friction's work is not stored (it is dissipated).
double shortRangeHalfEnergy(const ShortRangeForceLaw& law, const ContactPair& p, double volumeI);

}  // namespace pf
