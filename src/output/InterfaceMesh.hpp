#pragma once
// Peridigm's "Construct Interfaces" rule (Peridigm_ExodusDiscretization.cpp, constructInterfaceData): an interface
// element joins a point's element (self) to a bonded element of a later file position that shares a face with it.
// The elements' connectivity is kept whole, as node ids, in file order; only HEX8 and TET4 meshes are read.
#include <string>
#include <vector>

namespace pf {

struct MeshConnectivity {
  std::vector<long long> offsets = {0};  // element e's nodes: [offsets[e], offsets[e + 1]) of nodes
  std::vector<long long> nodes;          // node ids (the file's node map), element after element
  int size(int e) const { return static_cast<int>(offsets[e + 1] - offsets[e]); }
};

// The mesh file's elements (InputError naming the deck, 'Discretization/Construct Interfaces' and the file for an
// element that is not an 8-node hexahedron or a 4-node tetrahedron).
MeshConnectivity readConnectivity(const std::string& meshFile, const std::string& inputFile);

// Whether `self` and `neighbor` (file positions) share a face by Peridigm's rule; if so `nodes` gets the face's node
// ids (4: a quadrilateral, 3: a triangle). A hexahedron checks its six faces in Exodus order against the 8 ids that
// follow the neighbour's start in the element-after-element list (for a tetrahedron those run into the next
// elements', as Peridigm reads them; none past the end) and takes the first face with three of its nodes among them:
// its four nodes, a triangle of its first three if only three matched. Another element takes its nodes found among
// the neighbour's, in its own order, if there are three or more.
bool sharedFace(const MeshConnectivity& mesh, int self, int neighbor, std::vector<long long>& nodes);

}  // namespace pf
