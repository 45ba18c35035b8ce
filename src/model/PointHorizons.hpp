#pragma once
// The horizon of each point (Peridigm's per-point "Horizon" field, Peridigm_HorizonManager.cpp): its block's
// constant, or the block's expression in x, y, z at the point's reference coordinates. A value that is not a
// positive finite number is an InputError naming the block group and the point.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/Expression.hpp"
#include "discretization/Discretization.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

struct HorizonRule {
  double constant = 0.0;                          // used when expression is null
  std::shared_ptr<const Expression> expression;   // in x, y, z (t = 0)
  std::string where;                              // "input.xml: Blocks/Group D", for messages
};

// One horizon per point of points, from the rule of its block (every block of points has one). Throws the
// InputError on this rank only: a caller on several ranks wraps it in collectively (parallel/Collective.hpp).
std::vector<double> pointHorizons(const PointCloud& points, const std::map<int, HorizonRule>& ruleOf);

// Collective: true if every point of the whole body has the same horizon (then the per-point array is not needed).
bool uniformHorizon(const std::vector<double>& horizon, const Communicator& comm);

}  // namespace pf
