#pragma once
// One peridynamic point per mesh element (Peridigm's rule for Exodus meshes): its position and volume from
// the element's corner nodes. Solids are cut into tetrahedra, each face fanned from its barycentre to the
// element's centre (a hexahedron into Peridigm's 24); the centroid is the tetrahedra's volume-weighted mean.
// 2D elements give their area (the caller multiplies by the thickness). Higher-order elements use their corners.
#include <array>
#include <string>

namespace pf {

enum class ElementShape { Unknown, Sphere, Tet, Hex, Wedge, Pyramid, Quad, Tri };

// Exodus element type names (any case, as Cubit, Gmsh and seacas write them) -> shape.
ElementShape elementShape(const std::string& exodusType);
int cornerNodes(ElementShape shape);   // nodes the geometry reads (1 for a sphere)
bool isPlanarShape(ElementShape shape);

struct ElementGeometry {
  std::array<double, 3> centroid{};
  double measure = 0.0;                // volume (solids), area (2D); negative: inverted or misnumbered
};

// corners: cornerNodes(shape) nodes, x y z each, in Exodus node order. Not for spheres.
ElementGeometry elementGeometry(ElementShape shape, const double* corners);

}  // namespace pf
