#pragma once
// A pressure p(x, t) on a surface that the deck marks by its outer layer of points (a node set). Each
// layer point carries the body-force density b = p d / h: d is the unit direction into the material,
// estimated from the point's reference neighbours (the direction of sum_j xi_ij V_j), and h the layer
// thickness, so that a point of volume V stands for the surface area V / h and the layer's total force
// is p times the area. Positive p pushes on the body (compression), as a fluid pressure does.
#include <memory>
#include <string>
#include <vector>

#include "model/Model.hpp"

namespace pf {

// The pressure's three components as loads with per-node factors d_c / h, for the owned nodes of the set.
// Collective: every rank throws the same InputError (naming context) if a point of the set has neighbours on
// all sides (no surface there), or no neighbour at all, or (follower) is not on a band block's outer layer.
// follower: the loads are reference tractions the NDO band turns with the point's deformation
// (Model::addFollowerPressure); otherwise body forces (a dead load on the reference area).
std::vector<NodalLoad> pressureLoads(const Model& model, const std::vector<int>& nodes,
                                     std::shared_ptr<const Expression> pressure, double layerThickness,
                                     const std::string& context, bool follower = false);

}  // namespace pf
