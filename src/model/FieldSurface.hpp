#pragma once
// A nodal field's surface conditions on a layer of points (the node set marks the surface's outer layer, as for a
// Pressure): `Heat Flux` q(x, t) [W/m^2] into the body and `Convection` h (T_amb(x, t) - T) with a heat transfer
// coefficient h [W/(m^2 K)]. A layer point of volume V stands for the area V / l (l the layer thickness), so each
// adds q / l, resp. h / l (T_amb - T), to its rate per volume: the layer's total is q, resp. h (T_amb - T), times
// the area. Split for the solvers: the part linear in T (-h/l T and its diagonal h/l) joins the conduction operator,
// the rest is a source of the evaluated time.
#include <vector>

#include "model/NodalLoad.hpp"

namespace pf {

class FieldSurface {
 public:
  // value: q (flux) or T_amb (convection) at the load's nodes, per owned node.
  void addFlux(NodalLoad q, double layer);
  void addConvection(NodalLoad ambient, double h, double layer);
  bool empty() const { return terms_.empty(); }
  bool linear() const;  // some convection
  // out[i] += -h/l T_i; diag[i] += h/l (owned nodes).
  void addLinear(const double* T, double* out) const;
  void addDiagonal(double* diag) const;
  // out[i] += q/l + h/l T_amb at time t (x: 3 per overlap node).
  void addSource(double t, const std::vector<double>& x, double* out) const;

 private:
  struct Term {
    NodalLoad load;      // q or T_amb
    double h = 0.0;      // 0: a flux
    double layer = 0.0;  // l
  };
  std::vector<Term> terms_;
};

}  // namespace pf
