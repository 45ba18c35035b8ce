#pragma once
// Bond-based peridynamic heat conduction (the flux divergence Peridigm's "Diffusion" material computes):
//   h_i = sum_j c (T_j - T_i) / |xi_ij| V_j,   c = 6 k / (pi delta^4) in 3D,  6 k / (pi H delta^3) in 2D (thickness H),
// the constant for which h -> k lap T as delta -> 0 for a smooth T at a point whose family is whole (a Taylor
// expansion of T: sum over the ball of (xi . grad)^2 T / (2 |xi|) = pi delta^4 lap T / 6 in 3D, pi H delta^3 lap T / 6
// in 2D). Neighbours count with their partial volume where the discretization has one. Gather form: each owned
// node sums its own family (so a family cut by the surface conducts less: the surface effect, docs/thermal.md).
// Family normalisation (Periforge's `Thermal Conductivity`): the bond constant c_ij = 2 C k / (S_i + S_j), C = 6 in 3D
// and 4 in 2D, with S_i = sum_j |xi| V_j over i's own family (FieldOperator::nodeValue, ghosted by the model): the same
// limit, exact for a whole family on any lattice (the sum replaces the integral pi delta^4, which a lattice at
// delta = 3 dx misses by 10 %), and symmetric in i and j, so the bonds conserve heat (sum_i V_i h_i = 0) where two
// families differ, as at a surface (a per-node c_i = C k / S_i there lost half of a Heat Flux's heat in a bar).
#include <map>
#include <vector>

#include "core/Dimension.hpp"
#include "core/FieldOperator.hpp"

namespace pf {

class HeatConduction : public FieldOperator {
 public:
  // k: thermal conductivity (W/(m K)); capacity: rho c (J/(m^3 K)), 0 for steady solves only; thickness: 2D only.
  enum class Normalisation { Analytic, Family };
  // Volumes: V_j (times the partial-volume fraction); Moments: MomentQuadrature.hpp's weights (3D only).
  enum class Quadrature { Volumes, Moments };
  HeatConduction(double k, double capacity, Dimension dim, double thickness, Normalisation n = Normalisation::Analytic,
                 Quadrature q = Quadrature::Volumes);
  std::string field() const override { return "Temperature"; }
  void apply(const FamilyView& fam, const double* u, double* out) const override;
  void diagonal(const FamilyView& fam, double* diag) const override;
  double capacity() const override { return capacity_; }
  std::string nodeValueName() const override;
  void nodeValue(const FamilyView& fam, double* owned) const override;
  // c of the bond rule above for a block of horizon delta.
  double microconductivity(double delta) const;

 private:
  double k_, capacity_, thickness_;
  Dimension dim_;
  Normalisation norm_;
  Quadrature quadrature_;
  // Moments: the weights of each block's bonds, computed at the first evaluation (keyed by FamilyView::begin).
  mutable std::map<int, std::vector<double>> weights_;
  const double* bondWeights(const FamilyView& fam) const;
  // The bond constants' sum over i's intact bonds of c_ij V_j / |xi| weighting (u_j - u_i) (apply) or 1 (diagonal).
  template <class Term>
  double bondSum(const FamilyView& fam, const double* S, const double* w, int i, Term term) const;
  const double* familySums(const FamilyView& fam) const;
};

}  // namespace pf
