#pragma once
// Discretization "Gmsh": a Gmsh MSH 4.1 mesh (ASCII or binary) by Peridigm's rule for element meshes, as the
// Exodus reader applies it (ElementPoints.hpp): one point per element of the mesh's highest dimension at its
// centroid with its volume (2D: area * Thickness), in file order; blocks and node sets from the physical groups
// (input/GmshFile.hpp). Part `part` of `parts` keeps elements [N*part/parts, N*(part+1)/parts) and the
// coordinates of the nodes they name: the file streams through (the node sets' elements too), no rank holds
// the whole mesh. Bad meshes are InputErrors naming the mesh file.
#include <string>

#include "ElementPoints.hpp"

namespace pf {

PointCloud readGmshSlab(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts);

// The mesh nodes' bounding box and the count of elements that become points, for the size estimate.
MeshExtent gmshExtent(const DiscretizationSpec& spec, const std::string& inputFile);

}  // namespace pf
