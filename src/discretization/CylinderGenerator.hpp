#pragma once
// "Cylinder": a solid circular cylinder on the cubic lattice of spacing dx, its axis along x, y or z.
// Along the axis: Length/dx cell centres from the base face; across: the cell centres of a square
// 2R/dx x 2R/dx grid centred on the axis whose centres lie within the radius. Every point has volume dx^3.
#include <array>
#include <string>

#include "Discretization.hpp"

namespace pf {

// The in-plane offsets (a, b) from the axis of one cross-section, in the generator's order; the length
// of the cloud along the axis is cylinderLayers(). Both throw InputError naming the deck for a Length or
// diameter that is not a whole number of Spacings.
std::vector<std::array<double, 2>> cylinderSection(const DiscretizationSpec& d, const std::string& inputFile);
long cylinderLayers(const DiscretizationSpec& d, const std::string& inputFile);

// The points in cloud order into sink (its cloud gets the grid metadata).
void cylinder(const DiscretizationSpec& d, const std::string& inputFile, PointSink& sink);

}  // namespace pf
