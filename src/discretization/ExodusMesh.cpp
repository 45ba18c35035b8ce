#include "ExodusMesh.hpp"

#include <exodusII.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "ElementGeometry.hpp"
#include "core/InputError.hpp"
#include "input/ExodusFile.hpp"

namespace pf {

namespace {

// Nodes read per ex_get_partial_* call: bounds a rank's buffers at 24 MB of coordinates whatever the mesh size.
constexpr long long kChunk = 1 << 20;

// The elements a part reads, block by block: their connectivity (corner nodes, 1-based) and sphere volumes.
struct Elements {
  std::vector<int> nodes;          // every node of each element (corners first, in Exodus order), 1-based
  std::vector<int> offset;         // element e's nodes are nodes[offset[e], offset[e+1])
  std::vector<ElementShape> shape;
  std::vector<int> block;
  std::vector<double> sphereVolume;  // per element; 0 unless a sphere
};

std::string elementName(long long index) { return "element " + std::to_string(index + 1); }

Elements readElements(const ExodusFile& f, long long lo, long long hi, bool& planar) {
  Elements e;
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
    for (long long k = 0; k < n; ++k) {
      e.offset.push_back(static_cast<int>(e.nodes.size()));
      for (int c = 0; c < b.nodesPerElement; ++c) {
        const int node = conn[static_cast<std::size_t>(k * b.nodesPerElement + c)];
        if (node < 1 || node > f.summary().nodes)
          f.fail(elementName(from + k) + " (block " + std::to_string(b.id) + ") names node " + std::to_string(node) +
                 ", the mesh has nodes 1.." + std::to_string(f.summary().nodes));
        e.nodes.push_back(node);
      }
      e.shape.push_back(shape);
      e.block.push_back(static_cast<int>(b.id));
      e.sphereVolume.push_back(shape == ElementShape::Sphere ? attributes[static_cast<std::size_t>(k * b.attributes + 1)]
                                                            : 0.0);
    }
  }
  if (planar && solid) f.fail("it mixes 2D elements (QUAD, TRI) with 3D ones");
  e.offset.push_back(static_cast<int>(e.nodes.size()));
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

// The coordinates of the sorted, distinct nodes `wanted` (1-based), read chunk by chunk from the next wanted one.
std::vector<double> nodeCoordinates(const ExodusFile& f, const std::vector<int>& wanted) {
  std::vector<double> out(3 * wanted.size(), 0.0);
  std::vector<double> x[3];
  for (std::size_t w = 0; w < wanted.size();) {
    const long long start = wanted[w], count = readCoordinateChunk(f, start, x);
    for (; w < wanted.size() && wanted[w] < start + count; ++w)
      for (int a = 0; a < 3; ++a) out[3 * w + a] = x[a][static_cast<std::size_t>(wanted[w] - start)];
  }
  return out;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

PointCloud readExodusSlab(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts) {
  const ExodusFile f(spec.meshFile, inputFile);
  const long long total = f.summary().elements;
  if (total == 0) f.fail("it holds no elements");
  if (total > INT_MAX) f.fail("it has " + std::to_string(total) + " elements, more than 2147483647 (ids are ints)");
  const long long lo = total * part / parts, hi = total * (part + 1) / parts;
  bool planar = false;
  const Elements e = readElements(f, lo, hi, planar);
  if (planar && !(spec.thickness > 0.0))
    throw InputError(inputFile + ": Discretization/Thickness: the mesh '" + spec.meshFile +
                     "' has 2D elements (QUAD, TRI): give 'Thickness', the out-of-plane thickness");

  // Every node the part's elements touch, sorted, and each node's index into it.
  std::vector<int> wanted = e.nodes;
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  auto where = [&](int node) {
    return static_cast<std::size_t>(std::lower_bound(wanted.begin(), wanted.end(), node) - wanted.begin());
  };
  const std::vector<double> xyz = nodeCoordinates(f, wanted);

  PointCloud c;
  c.numGlobal = total;
  c.influence = spec.influence;
  c.planar = planar;
  c.thickness = planar ? spec.thickness : 0.0;
  const int n = static_cast<int>(e.shape.size());
  std::vector<double> corners;
  for (int k = 0; k < n; ++k) {
    const long long index = lo + k;
    const int first = e.offset[k], count = cornerNodes(e.shape[k]);
    corners.resize(3 * static_cast<std::size_t>(count));
    for (int m = 0; m < count; ++m) {
      const std::size_t at = where(e.nodes[first + m]);
      for (int i = 0; i < 3; ++i) corners[3 * m + i] = xyz[3 * at + i];
    }
    ElementGeometry g;
    if (e.shape[k] == ElementShape::Sphere) {
      g.centroid = {corners[0], corners[1], corners[2]};
      g.measure = e.sphereVolume[k];
    } else {
      g = elementGeometry(e.shape[k], corners.data());
    }
    if (!(g.measure > 0.0))
      f.fail(elementName(index) + " (block " + std::to_string(e.block[k]) + ") has " +
             (e.shape[k] == ElementShape::Sphere ? "volume attribute " : planar ? "area " : "volume ") + num(g.measure) +
             (e.shape[k] == ElementShape::Sphere ? "" : " (inverted, degenerate or misnumbered)"));
    c.gid.push_back(static_cast<int>(index));
    c.x.insert(c.x.end(), g.centroid.begin(), g.centroid.end());
    c.volume.push_back(planar ? g.measure * spec.thickness : g.measure);
    c.block.push_back(e.block[k]);
  }

  // Node sets: the file's list streams through in chunks; an element is in the set when one of its nodes is.
  std::vector<int> ids;
  for (const ExodusNodeSet& s : f.summary().nodeSets) {
    if (s.nodes == 0) continue;  // names no element; the deck parser left it out of the set names too
    std::vector<char> marked(wanted.size(), 0);
    for (long long start = 1; start <= s.nodes; start += kChunk) {
      const long long count = std::min(kChunk, s.nodes - start + 1);
      ids.assign(static_cast<std::size_t>(count), 0);
      f.check(ex_get_partial_node_set(f.id(), s.id, start, count, ids.data()), "ex_get_partial_node_set");
      for (int node : ids) {
        if (node < 1 || node > f.summary().nodes)
          f.fail("node set '" + s.name + "' names node " + std::to_string(node) + ", the mesh has nodes 1.." +
                 std::to_string(f.summary().nodes));
        const std::size_t at = where(node);
        if (at < wanted.size() && wanted[at] == node) marked[at] = 1;
      }
    }
    std::vector<int>& members = c.generatedNodeSets[s.name];
    for (int k = 0; k < n; ++k)
      for (int m = e.offset[k]; m < e.offset[k + 1]; ++m)
        if (marked[where(e.nodes[m])]) {
          members.push_back(c.gid[k]);
          break;
        }
  }
  return c;
}

ExodusExtent exodusExtent(const DiscretizationSpec& spec, const std::string& inputFile) {
  const ExodusFile f(spec.meshFile, inputFile);
  ExodusExtent e;
  e.elements = f.summary().elements;
  e.lo.fill(HUGE_VAL), e.hi.fill(-HUGE_VAL);
  std::vector<double> x[3];
  for (long long start = 1; start <= f.summary().nodes; start += kChunk) {
    readCoordinateChunk(f, start, x);
    for (int a = 0; a < 3; ++a)
      for (double v : x[a]) e.lo[a] = std::min(e.lo[a], v), e.hi[a] = std::max(e.hi[a], v);
  }
  return e;
}

}  // namespace pf
