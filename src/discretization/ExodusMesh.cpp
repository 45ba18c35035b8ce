#include "ExodusMesh.hpp"

#include <exodusII.h>

#include <algorithm>
#include <climits>

#include "ElementPoints.hpp"
#include "core/InputError.hpp"
#include "input/ExodusFile.hpp"

namespace pf {

namespace {

// Nodes read per ex_get_partial_* call: bounds a rank's buffers at 24 MB of coordinates whatever the mesh size.
constexpr long long kChunk = 1 << 20;

// The elements [lo, hi) of the file order, block by block: their connectivity and sphere volumes.
MeshElements readElements(const ExodusFile& f, long long lo, long long hi, bool& planar) {
  MeshElements e;
  bool solid = false;
  for (const ExodusBlock& b : f.summary().blocks) {
    const long long from = std::max(lo, b.first), to = std::min(hi, b.first + b.elements);
    if (b.elements == 0) continue;
    const ElementShape shape = elementShape(b.type);
    if (shape == ElementShape::Unknown)
      f.fail("block " + std::to_string(b.id) + " has element type '" + b.type +
             "' (known: SPHERE, TET/TETRA, HEX, WEDGE, PYRAMID, QUAD, TRI and their higher-order forms)");
    const int corners = cornerNodes(shape);
    if (b.nodesPerElement < corners)
      f.fail("block " + std::to_string(b.id) + ": a " + b.type + " element needs " + std::to_string(corners) +
             " nodes, the block has " + std::to_string(b.nodesPerElement));
    if (shape == ElementShape::Sphere && b.attributes < 2)
      f.fail("block " + std::to_string(b.id) + ": SPHERE elements need their volume as the second attribute, the "
             "block has " + std::to_string(b.attributes) + " attribute(s)");
    (isPlanarShape(shape) ? planar : solid) = true;
    if (from >= to) continue;
    const long long n = to - from;
    std::vector<int> conn(static_cast<std::size_t>(n * b.nodesPerElement));
    f.check(ex_get_partial_conn(f.id(), EX_ELEM_BLOCK, b.id, from - b.first + 1, n, conn.data(), nullptr, nullptr),
            "ex_get_partial_conn");
    std::vector<double> attributes;
    if (shape == ElementShape::Sphere) {
      attributes.resize(static_cast<std::size_t>(n * b.attributes));
      f.check(ex_get_partial_attr(f.id(), EX_ELEM_BLOCK, b.id, from - b.first + 1, n, attributes.data()),
              "ex_get_partial_attr");
    }
    std::vector<long long> nodes(static_cast<std::size_t>(b.nodesPerElement));
    for (long long k = 0; k < n; ++k) {
      for (int c = 0; c < b.nodesPerElement; ++c) {
        const int node = conn[static_cast<std::size_t>(k * b.nodesPerElement + c)];
        if (node < 1 || node > f.summary().nodes)
          f.fail("element " + std::to_string(from + k + 1) + " (block " + std::to_string(b.id) + ") names node " +
                 std::to_string(node) + ", the mesh has nodes 1.." + std::to_string(f.summary().nodes));
        nodes[c] = node;
      }
      e.add(shape, static_cast<int>(b.id), from + k + 1, nodes.data(), b.nodesPerElement,
            shape == ElementShape::Sphere ? attributes[static_cast<std::size_t>(k * b.attributes + 1)] : 0.0);
    }
  }
  if (planar && solid) f.fail("it mixes 2D elements (QUAD, TRI) with 3D ones");
  return e;
}

// The coordinates of the nodes [start, start + count) (1-based) of at most kChunk nodes, into x[0..2]; z = 0 in 2D.
// Returns count, cut at the last node.
long long readCoordinateChunk(const ExodusFile& f, long long start, std::vector<double> (&x)[3]) {
  const long long count = std::min<long long>(kChunk, f.summary().nodes - start + 1);
  for (auto& c : x) c.assign(static_cast<std::size_t>(count), 0.0);
  f.check(ex_get_partial_coord(f.id(), start, count, x[0].data(), x[1].data(),
                               f.summary().dimension > 2 ? x[2].data() : nullptr),
          "ex_get_partial_coord");
  return count;
}

// The coordinates of the nodes n.ids (1-based, sorted), read chunk by chunk from the next wanted one.
void readNodeCoordinates(const ExodusFile& f, MeshNodes& n) {
  std::vector<double> x[3];
  for (std::size_t w = 0; w < n.ids.size();) {
    const long long start = n.ids[w], count = readCoordinateChunk(f, start, x);
    for (; w < n.ids.size() && n.ids[w] < start + count; ++w)
      for (int a = 0; a < 3; ++a) n.xyz[3 * w + a] = x[a][static_cast<std::size_t>(n.ids[w] - start)];
  }
}

// Node set s: its list streams through in chunks and marks the part's nodes it names.
std::vector<char> markedNodes(const ExodusFile& f, const ExodusNodeSet& s, const MeshNodes& n) {
  std::vector<char> marked(n.ids.size() + 1, 0);  // the last entry: find()'s "not held"
  std::vector<int> ids;
  for (long long start = 1; start <= s.nodes; start += kChunk) {
    const long long count = std::min(kChunk, s.nodes - start + 1);
    ids.assign(static_cast<std::size_t>(count), 0);
    f.check(ex_get_partial_node_set(f.id(), s.id, start, count, ids.data()), "ex_get_partial_node_set");
    for (int node : ids) {
      if (node < 1 || node > f.summary().nodes)
        f.fail("node set '" + s.name + "' names node " + std::to_string(node) + ", the mesh has nodes 1.." +
               std::to_string(f.summary().nodes));
      marked[n.find(node)] = 1;
    }
  }
  marked.back() = 0;
  return marked;
}

}  // namespace

PointCloud readExodusSlab(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts) {
  const ExodusFile f(spec.meshFile, inputFile);
  const long long total = f.summary().elements;
  if (total == 0) f.fail("it holds no elements");
  if (total > INT_MAX) f.fail("it has " + std::to_string(total) + " elements, more than 2147483647 (ids are ints)");
  const long long lo = total * part / parts, hi = total * (part + 1) / parts;
  bool planar = false;
  const MeshElements e = readElements(f, lo, hi, planar);
  MeshNodes n(e);
  readNodeCoordinates(f, n);
  PointCloud c = elementPoints(e, n, lo, total, planar, spec, inputFile, [&](const std::string& m) { f.fail(m); });
  for (const ExodusNodeSet& s : f.summary().nodeSets)
    if (s.nodes > 0)  // an empty set names no element; the deck parser left it out of the set names too
      addElementNodeSet(c, s.name, e, n, markedNodes(f, s, n));
  return c;
}

MeshExtent exodusExtent(const DiscretizationSpec& spec, const std::string& inputFile) {
  const ExodusFile f(spec.meshFile, inputFile);
  MeshExtent e;
  e.elements = f.summary().elements;
  std::vector<double> x[3];
  for (long long start = 1; start <= f.summary().nodes; start += kChunk) {
    const long long count = readCoordinateChunk(f, start, x);
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
      const double p[3] = {x[0][k], x[1][k], x[2][k]};
      e.include(p);
    }
  }
  return e;
}

}  // namespace pf
