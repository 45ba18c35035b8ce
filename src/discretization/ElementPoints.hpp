#pragma once
// Peridigm's rule for element meshes, shared by the Exodus (ExodusMesh.hpp) and Gmsh (GmshMesh.hpp) readers: one
// point per element at its centroid with its volume (ElementGeometry.hpp; 2D elements: area * Thickness; a sphere
// element at its node with its volume attribute), and a node set of the file as the elements that touch one of
// its nodes. A reader fills MeshElements with the elements its part holds and MeshNodes with the coordinates of
// the nodes they name; nothing here sees the file format.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "Discretization.hpp"
#include "ElementGeometry.hpp"

namespace pf {

// The elements a part holds, in cloud order.
struct MeshElements {
  std::vector<long long> nodes;      // every node of each element (corners first), as the file numbers them
  std::vector<int> offset{0};        // element e's nodes are nodes[offset[e], offset[e+1])
  std::vector<ElementShape> shape;
  std::vector<int> block;            // block id ("block_<id>")
  std::vector<long long> label;      // the element's number in messages ("element <label>")
  std::vector<double> sphereVolume;  // 0 unless a sphere
  void add(ElementShape s, int blockId, long long labelId, const long long* first, int count, double sphere = 0.0);
  int size() const { return static_cast<int>(shape.size()); }
};

// The distinct nodes the elements name (sorted) and their coordinates, 3 per node (z = 0 in 2D).
struct MeshNodes {
  std::vector<long long> ids;
  std::vector<double> xyz;
  explicit MeshNodes(const MeshElements& e);  // ids from the elements; xyz zero, for the reader to fill
  // ids' index of node id, or ids.size() if the elements name no such node.
  std::size_t find(long long id) const;
};

// The part's points: gid firstIndex + k for element k of numGlobal, volume and centroid from the corners
// (planar: area times spec.thickness, which must be given). Bad elements call fail(message) (it throws an
// InputError naming the mesh file): a non-positive volume names the element and its block.
PointCloud elementPoints(const MeshElements& e, const MeshNodes& n, long long firstIndex, long long numGlobal,
                         bool planar, const DiscretizationSpec& spec, const std::string& inputFile,
                         const std::function<void(const std::string&)>& fail);

// A mesh's node bounding box and the count of its elements that become points (for the size estimate).
struct MeshExtent {
  long long elements = 0;
  std::array<double, 3> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void include(const double* p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
};

// Adds node set `name` to the cloud: the points whose element names a node with marked[n.find(node)] set.
void addElementNodeSet(PointCloud& c, const std::string& name, const MeshElements& e, const MeshNodes& n,
                       const std::vector<char>& marked);

}  // namespace pf
