#include "InterfaceMesh.hpp"

#include <exodusII.h>

#include "input/ExodusFile.hpp"
#include "input/ExodusNodalData.hpp"

namespace pf {

MeshConnectivity readConnectivity(const std::string& meshFile, const std::string& inputFile) {
  const ExodusFile f(meshFile, inputFile, "Discretization/Construct Interfaces");
  const std::vector<long long> ids = exodusIdMap(f, true);
  MeshConnectivity m;
  for (const ExodusBlock& b : f.summary().blocks) {
    if (b.elements == 0) continue;
    const bool hex = b.type.compare(0, 3, "HEX") == 0 && b.nodesPerElement == 8;
    const bool tet = b.type.compare(0, 3, "TET") == 0 && b.nodesPerElement == 4;
    if (!hex && !tet)
      f.fail("block " + std::to_string(b.id) + " has " + std::to_string(b.nodesPerElement) + "-node " + b.type +
             " elements; interfaces are built between HEX8 and TET4 elements only (Peridigm's rule)");
    std::vector<int> conn(static_cast<std::size_t>(b.elements * b.nodesPerElement));
    f.check(ex_get_conn(f.id(), EX_ELEM_BLOCK, b.id, conn.data(), nullptr, nullptr), "ex_get_conn");
    for (long long e = 0; e < b.elements; ++e) {
      for (long long c = 0; c < b.nodesPerElement; ++c) {
        const int node = conn[static_cast<std::size_t>(e * b.nodesPerElement + c)];
        if (node < 1 || node > f.summary().nodes) f.fail("an element names node " + std::to_string(node));
        m.nodes.push_back(ids[static_cast<std::size_t>(node - 1)]);
      }
      m.offsets.push_back(static_cast<long long>(m.nodes.size()));
    }
  }
  return m;
}

bool sharedFace(const MeshConnectivity& mesh, int self, int neighbor, std::vector<long long>& nodes) {
  static const int kHexFaces[6][4] = {{4, 5, 6, 7}, {7, 6, 2, 3}, {0, 4, 7, 3}, {0, 1, 2, 3}, {0, 4, 5, 1}, {1, 5, 6, 2}};
  const int n = mesh.size(self);
  const long long* mine = &mesh.nodes[static_cast<std::size_t>(mesh.offsets[self])];
  // The neighbour's ids as Peridigm reads them: as many as self has, from the neighbour's start on.
  std::vector<long long> theirs;
  for (long long k = mesh.offsets[neighbor]; k < mesh.offsets[neighbor] + n; ++k)
    theirs.push_back(k < static_cast<long long>(mesh.nodes.size()) ? mesh.nodes[static_cast<std::size_t>(k)] : -1);
  nodes.clear();
  if (n == 8) {
    for (const auto& face : kHexFaces) {
      int found = 0;
      for (int c : face)
        for (long long t : theirs) found += mine[c] == t;
      if (found > 2) {
        for (int c = 0; c < found && c < 4; ++c) nodes.push_back(mine[face[c]]);
        return true;
      }
    }
    return false;
  }
  for (int a = 0; a < n; ++a)
    for (long long t : theirs)
      if (mine[a] == t) nodes.push_back(mine[a]);
  if (nodes.size() > 2) return true;
  nodes.clear();
  return false;
}

}  // namespace pf
