#pragma once
// The position-aware influence functions of Peridigm's "Pals" solid (Mitchell, Silling & Littlewood, "A
// position-aware linear solid constitutive model for peridynamics", J. Mech. Mater. Struct. 10 (2015); Peridigm's
// pals.h / pals.cxx). For the bond z of point X, with r = |z|:
//   omega(z) = omega0(r) + sum_k lambda_k e_k(z),   e(z)   = (a^2, b^2, c^2, 2ab, 2ac, 2bc),            z = (a, b, c)
//   sigma(z) = sigma0(r) + sum_k tau_k eps_k(z)^2,  eps(z) = (a^2/r - r/3, b^2/r - r/3, c^2/r - r/3, 2ab/r, 2ac/r, 2bc/r)
// where the 6 + 6 Lagrange multipliers of X make its discrete family reproduce the continuum moments:
//   sum_j omega e_k V_j = (1, 1, 1, 0, 0, 0)_k       (so theta = sum omega |z| e V_j is tr(eps) for any small strain)
//   sum_j sigma eps_k^2 V_j = (2/3, 2/3, 2/3, 2, 2, 2)_k  (eps_dev : eps_dev of the six unit strain modes)
// Plain arithmetic, the same operations in the same order as Peridigm's, so that round-off follows its.
namespace pf {
namespace pals {

constexpr int kModes = 6;

struct Multipliers {
  double dilatation[kModes];  // lambda: Peridigm's Lagrange_Multiplier_Dilatation_1..6
  double deviatoric[kModes];  // tau: Lagrange_Multiplier_Deviatoric_1..6
};

// omega(z) and sigma(z) given omega0(|z|), sigma0(|z|) and the point's multipliers (Peridigm's pals_influence with
// its normalising constant 1).
double omega(const double* z, double omega0, const double* lambda);
double sigma(const double* z, double sigma0, const double* tau);

// The two 6x6 systems of one point, accumulated bond by bond, then solved.
class MultiplierSystem {
 public:
  MultiplierSystem();
  // One bond z of the family with neighbour volume v and the base influence values omega0, sigma0 at |z|.
  void add(const double* z, double v, double omega0, double sigma0);
  // The multipliers. A mode no bond of the family spans (e.g. every z in one plane) is decoupled with multiplier 0,
  // as Peridigm does; returns false if a system is still singular (too few bonds in general position).
  bool solve(Multipliers& out) const;

 private:
  double kDil_[kModes * kModes], kDev_[kModes * kModes];
  double rhsDil_[kModes], rhsDev_[kModes];
};

}  // namespace pals
}  // namespace pf
