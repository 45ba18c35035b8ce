#pragma once
// Discretization "Exodus" (Peridigm's): one point per element of a genesis mesh at the element's centroid with
// its volume (ElementGeometry.hpp; a sphere element at its node with its volume attribute), element block
// <id> -> block id <id>, and each node set of the file as the elements that touch one of its nodes (Peridigm's
// rule), under its name or "nodelist_<id>". Part `part` of `parts` reads elements [N*part/parts, N*(part+1)/parts)
// in file order (their gids) with ex_get_partial_*: the coordinates and node sets stream through in chunks, so
// no rank holds the whole mesh. Bad meshes (unknown element type, non-positive volume, 2D elements without a
// Thickness, node ids out of range) are InputErrors naming the mesh file and the element.
#include <string>

#include "ElementPoints.hpp"

namespace pf {

PointCloud readExodusSlab(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts);

// The mesh nodes' bounding box (coordinates read in chunks) and the element count, for the size estimate.
MeshExtent exodusExtent(const DiscretizationSpec& spec, const std::string& inputFile);

}  // namespace pf
