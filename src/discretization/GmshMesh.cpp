#include "GmshMesh.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

#include "ElementPoints.hpp"
#include "input/GmshFile.hpp"

namespace pf {

namespace {

// The elements [lo, hi) of the cloud order (the top dimension's, in file order).
MeshElements readElements(const GmshFile& f, long long lo, long long hi) {
  MeshElements e;
  for (const GmshElementBlock& b : f.summary().blocks) {
    const long long from = std::max(lo, b.first), to = std::min(hi, b.first + b.elements);
    if (b.first < 0 || from >= to) continue;
    const ElementShape shape = elementShape(b.exodusType);
    if (shape == ElementShape::Unknown) throw std::logic_error("GmshFile's type table names an unknown shape");
    f.forEachElement(b, from - b.first, to - from, [&](long long tag, const long long* nodes) {
      e.add(shape, b.block, tag, nodes, b.nodesPerElement);
    });
  }
  return e;
}

// Which node tags the file holds: a bit per tag of [min, max] when the tags are about dense (Gmsh numbers
// them 1..N), else the sorted tags (8 bytes a node: a mesh renumbered with gaps).
class NodeTags {
 public:
  // keep: false when no node set asks (nothing is stored).
  NodeTags(const GmshSummary& s, bool keep) : min_(s.minNodeTag), span_(keep ? s.maxNodeTag - s.minNodeTag + 1 : 0) {
    dense_ = span_ <= 64 * s.nodes + (1 << 20);
    if (dense_) bits_.assign(static_cast<std::size_t>(std::max(0LL, span_)), false);
  }
  void add(long long tag) {
    if (!dense_) sorted_.push_back(tag);
    else if (tag >= min_ && tag - min_ < span_) bits_[static_cast<std::size_t>(tag - min_)] = true;
  }
  void done() { std::sort(sorted_.begin(), sorted_.end()); }
  bool has(long long tag) const {
    if (!dense_) return std::binary_search(sorted_.begin(), sorted_.end(), tag);
    return tag >= min_ && tag - min_ < span_ && bits_[static_cast<std::size_t>(tag - min_)];
  }

 private:
  long long min_, span_;
  bool dense_ = true;
  std::vector<bool> bits_;
  std::vector<long long> sorted_;
};

// The coordinates of the nodes n names; every node must be in $Nodes. tags: filled with every tag the file holds.
void readNodes(const GmshFile& f, const MeshElements& e, MeshNodes& n, NodeTags* tags) {
  std::vector<char> found(n.ids.size(), 0);
  f.forEachNode([&](long long tag, const double* xyz) {
    if (tags) tags->add(tag);
    const std::size_t at = n.find(tag);
    if (at == n.ids.size()) return;
    std::copy(xyz, xyz + 3, n.xyz.begin() + 3 * static_cast<std::ptrdiff_t>(at));
    found[at] = 1;
  });
  if (tags) tags->done();
  for (int k = 0; k < e.size(); ++k)
    for (int m = e.offset[k]; m < e.offset[k + 1]; ++m)
      if (!found[n.find(e.nodes[m])])
        f.fail("element " + std::to_string(e.label[k]) + " (block " + std::to_string(e.block[k]) + ") names node " +
               std::to_string(e.nodes[m]) + ", which $Nodes does not hold");
}

// Each node set's marks on the part's nodes: the nodes of its physical group's elements (streamed block by
// block); a node the file does not hold is an error.
std::vector<std::vector<char>> markNodeSets(const GmshFile& f, const MeshNodes& n, const NodeTags& tags) {
  const GmshSummary& s = f.summary();
  std::vector<std::vector<char>> marked(s.nodeSets.size(), std::vector<char>(n.ids.size() + 1, 0));
  for (const GmshElementBlock& b : s.blocks) {
    if (b.nodeSets.empty()) continue;
    f.forEachElement(b, 0, b.elements, [&](long long tag, const long long* nodes) {
      for (int m = 0; m < b.nodesPerElement; ++m) {
        if (!tags.has(nodes[m]))
          f.fail("node set '" + s.nodeSets[b.nodeSets[0]].name + "': its element " + std::to_string(tag) +
                 " names node " + std::to_string(nodes[m]) + ", which $Nodes does not hold");
        const std::size_t at = n.find(nodes[m]);
        for (int set : b.nodeSets) marked[set][at] = 1;
      }
    });
  }
  return marked;
}

}  // namespace

PointCloud readGmshSlab(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts) {
  const GmshFile f(spec.meshFile, inputFile);
  const GmshSummary& s = f.summary();
  const long long total = s.elements;
  if (total > INT_MAX) f.fail("it has " + std::to_string(total) + " elements, more than 2147483647 (ids are ints)");
  const long long lo = total * part / parts, hi = total * (part + 1) / parts;
  const MeshElements e = readElements(f, lo, hi);
  MeshNodes n(e);
  NodeTags tags(s, !s.nodeSets.empty());
  readNodes(f, e, n, s.nodeSets.empty() ? nullptr : &tags);
  PointCloud c = elementPoints(e, n, lo, total, s.dimension == 2, spec, inputFile,
                               [&](const std::string& m) { f.fail(m); });
  const std::vector<std::vector<char>> marked = markNodeSets(f, n, tags);
  for (std::size_t k = 0; k < s.nodeSets.size(); ++k) addElementNodeSet(c, s.nodeSets[k].name, e, n, marked[k]);
  return c;
}

MeshExtent gmshExtent(const DiscretizationSpec& spec, const std::string& inputFile) {
  const GmshFile f(spec.meshFile, inputFile);
  MeshExtent x;
  x.elements = f.summary().elements;
  f.forEachNode([&](long long, const double* p) { x.include(p); });
  return x;
}

}  // namespace pf
