#pragma once
// Bond-based peridynamic heat conduction (the flux divergence Peridigm's "Diffusion" material computes):
//   h_i = sum_j c (T_j - T_i) / |xi_ij| V_j,   c = 6 k / (pi delta^4) in 3D,  6 k / (pi H delta^3) in 2D (thickness H),
// the constant for which h -> k lap T as delta -> 0 for a smooth T at a point whose family is whole (a Taylor
// expansion of T: sum over the ball of (xi . grad)^2 T / (2 |xi|) = pi delta^4 lap T / 6 in 3D, pi H delta^3 lap T / 6
// in 2D). Neighbours count with their partial volume where the discretization has one. Gather form: each owned
// node sums its own family (so a family cut by the surface conducts less: the surface effect, docs/thermal.md).
// Family normalisation (Periforge's `Thermal Conductivity`): c_i = 6 k / S_i in 3D, 4 k / S_i in 2D, with
// S_i = sum_j |xi| V_j over i's own family: the same limit, but exact for a whole family on any lattice (the sum
// replaces the integral pi delta^4, which a lattice at delta = 3 dx misses by 10 %), and a family cut by a surface
// parallel to the gradient conducts as a whole one.
#include "core/Dimension.hpp"
#include "core/FieldOperator.hpp"

namespace pf {

class HeatConduction : public FieldOperator {
 public:
  // k: thermal conductivity (W/(m K)); capacity: rho c (J/(m^3 K)), 0 for steady solves only; thickness: 2D only.
  enum class Normalisation { Analytic, Family };
  HeatConduction(double k, double capacity, Dimension dim, double thickness, Normalisation n = Normalisation::Analytic);
  std::string field() const override { return "Temperature"; }
  void apply(const FamilyView& fam, const double* u, double* out) const override;
  void diagonal(const FamilyView& fam, double* diag) const override;
  double capacity() const override { return capacity_; }
  // c of the bond rule above for a block of horizon delta.
  double microconductivity(double delta) const;

 private:
  double k_, capacity_, thickness_;
  Dimension dim_;
  Normalisation norm_;
  // c for a node whose family sum of |xi| V_j is familySum: analytic (the sum unused) or family-normalised.
  double nodeConstant(const FamilyView& fam, double familySum) const;
};

}  // namespace pf
