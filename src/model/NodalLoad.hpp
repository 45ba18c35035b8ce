#pragma once
// A condition imposed on owned nodes: a displacement, velocity or body-force component, or a scalar field's value
// (Temperature: coordinate 0 of a one-component field), value(x, t) times factor[k] at nodes[k] when factor is given
// (a pressure's share per node and direction).
#include <memory>
#include <vector>

#include "core/Expression.hpp"

namespace pf {

struct NodalLoad {
  std::vector<int> nodes;  // owned-local indices
  int coordinate = 0;
  std::shared_ptr<const Expression> value;
  std::vector<double> factor;  // empty: 1 at every node
};

// Calls apply(components * node + coordinate, value) for each of the load's nodes at time t (x: 3 per node);
// an expression without x, y, z is evaluated once.
template <class Apply>
void forEachLoadValue(const NodalLoad& load, const std::vector<double>& x, double t, int components, Apply apply) {
  const bool scaled = !load.factor.empty();
  const std::size_t n = load.nodes.size();
  if (!load.value->dependsOnSpace()) {
    const double v = (*load.value)(0.0, 0.0, 0.0, t);
    for (std::size_t k = 0; k < n; ++k)
      apply(components * load.nodes[k] + load.coordinate, scaled ? v * load.factor[k] : v);
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const int i = load.nodes[k];
    const double v = (*load.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t);
    apply(components * i + load.coordinate, scaled ? v * load.factor[k] : v);
  }
}

}  // namespace pf
