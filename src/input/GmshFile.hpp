#pragma once
// A Gmsh MSH 4.1 mesh (ASCII or binary) opened for reading, and its summary: what the deck parser needs (the
// node-set and block names) and what the discretization needs to read its share of the elements. Opening scans
// the file once without keeping its nodes or elements: the physical groups of each entity, where $Nodes starts
// and where each element block's records start.
//
// Peridigm's element rule applies to the elements of the mesh's highest dimension (3, or 2 for a planar mesh): in
// file order they are the cloud's points. Their block is the physical group of their entity, block_<tag> (a named
// group's name is an alias of it); a mesh without physical groups of that dimension has block_<entity tag>. A
// physical group of a lower dimension is a node set named by its physical name, or "nodelist_<tag>" when it has
// none: its nodes are those of its elements. Errors are InputErrors "deck: parameter: mesh file 'path': ...".
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "MshStream.hpp"

namespace pf {

// A Gmsh element type: its dimension, node count and the Exodus name of its shape (corners first, in the same
// order); exodus "" for lines and points, which only carry node sets.
struct GmshElementType {
  int type, dim, nodes;
  const char* exodus;
};
const GmshElementType* gmshElementType(int type);  // null if Periforge does not know it

struct GmshElementBlock {
  int dim = 0, entity = 0, type = 0, nodesPerElement = 0;
  long long elements = 0;
  long long position = 0;       // where its records start
  std::string exodusType;       // its shape's Exodus name ("HEX8", ...)
  long long first = -1;         // top dimension: its first element's index in the cloud order; else -1
  int block = 0;                // top dimension: its block id
  std::vector<int> nodeSets;    // lower dimensions: the node sets (indices into GmshSummary::nodeSets) it feeds
};

struct GmshNodeSet {
  int dim = 0, tag = 0;
  std::string name;             // the physical name, or "nodelist_<tag>"
};

struct GmshSummary {
  int dimension = 0;            // of the elements that become points
  long long elements = 0;       // of that dimension
  long long nodes = 0, minNodeTag = 0, maxNodeTag = 0;
  long long nodesPosition = 0;  // the first node block's header
  std::vector<GmshElementBlock> blocks;                 // every element block, in file order
  std::vector<GmshNodeSet> nodeSets;
  std::vector<std::pair<std::string, int>> blockNames;  // a named physical group of the top dimension -> its tag
};

class GmshFile {
 public:
  GmshFile(const std::string& path, const std::string& inputFile,
           const std::string& parameter = "Discretization/Input Mesh File");
  ~GmshFile();
  const GmshSummary& summary() const { return summary_; }
  [[noreturn]] void fail(const std::string& msg) const;

  // Every node in file order: its tag and x, y, z.
  void forEachNode(const std::function<void(long long tag, const double* xyz)>& use) const;
  // Elements [skip, skip + count) of block b: their tags and nodes (b.nodesPerElement of them).
  void forEachElement(const GmshElementBlock& b, long long skip, long long count,
                      const std::function<void(long long tag, const long long* nodes)>& use) const;

 private:
  void readFormat();
  void readPhysicalNames();
  void readEntities();
  void scanNodes();
  void scanElements();
  void summarize();
  std::string path_, inputFile_, parameter_;
  std::unique_ptr<MshStream> in_;
  GmshSummary summary_;
  struct Scan;                   // the physical names and the entities' physical groups, while scanning
  std::unique_ptr<Scan> scan_;
};

}  // namespace pf
