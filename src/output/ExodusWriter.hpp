#pragma once
// Merged ExodusII output laid out like Peridigm's, so that gold files from Peridigm and
// Periforge results can be compared with scripts/exodiff.py (see docs/output.md).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pf {

// Which element block each node is in, as runs of consecutive nodes of one block id (a few per block, not an
// entry per node), so a writer can be made without a whole per-node list: the ids come a piece at a time.
class BlockRuns {
 public:
  struct Run {
    std::size_t begin, end;  // nodes [begin, end)
    int id;                  // 1-based block id
  };
  BlockRuns() = default;
  explicit BlockRuns(const std::vector<int>& blockIdPerNode) { add(blockIdPerNode.data(), blockIdPerNode.size()); }
  void add(const int* ids, std::size_t count);  // the block ids of the next count nodes
  std::size_t numNodes() const { return numNodes_; }
  const std::vector<Run>& runs() const { return runs_; }

 private:
  std::vector<Run> runs_;
  std::size_t numNodes_ = 0;
};

// Writes one merged file. Construct it on rank 0 only: the ExodusII C library is not
// thread/rank aware and every array passed in is already gathered in global-id order.
//
// Layout: 3 spatial dimensions always (planar runs get z = as given, usually 0, and zero Z
// components) because Peridigm output is 3D and exodiff compares DisplacementZ etc.;
// one element block per distinct block id, SPHERE elements with one node each; element of
// node g has element number g+1; the initial state is expected as the first writeStep.
class ExodusWriter {
 public:
  // coords: 3 per node, or empty: the caller then writes them with writeCoordinates (every node, before the
  // file is closed), so that no whole coordinate array is needed. blocks (or blockIdPerNode, the same as a
  // whole list): each node's 1-based block id.
  // nodalVectorNames "Displacement" -> variables DisplacementX, DisplacementY, DisplacementZ.
  // Throws std::runtime_error (naming the file) on any ExodusII failure or bad sizes.
  // append: continue a file this writer wrote with the same arguments (a restart): it is opened, not
  // created, and the next writeStep follows its last step; a file with other variables is an error.
  // elementVariablesOf: per block id, one flag per element scalar: whether the block has it (Peridigm leaves a
  // variable out of the blocks whose material lacks it: the Exodus truth table); a block not listed has all.
  ExodusWriter(const std::string& filename, const std::vector<double>& coords, const BlockRuns& blocks, bool planar,
               const std::vector<std::string>& nodalVectorNames,
               const std::vector<std::string>& nodalScalarNames,
               const std::vector<std::string>& elementScalarNames,
               const std::vector<std::string>& globalNames = {}, bool append = false,
               const std::map<int, std::vector<char>>& elementVariablesOf = {});
  ExodusWriter(const std::string& filename, const std::vector<double>& coords,
               const std::vector<int>& blockIdPerNode, bool planar,
               const std::vector<std::string>& nodalVectorNames,
               const std::vector<std::string>& nodalScalarNames,
               const std::vector<std::string>& elementScalarNames,
               const std::vector<std::string>& globalNames = {}, bool append = false)
      : ExodusWriter(filename, coords, BlockRuns(blockIdPerNode), planar, nodalVectorNames, nodalScalarNames,
                     elementScalarNames, globalNames, append) {}
  ~ExodusWriter();

  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  // Every declared name must be present with the right length (3*N for vectors, N otherwise);
  // element scalars are given per node in global order; globals one value each. Extra map entries are ignored so the
  // caller can pass one big field map. The file is synced after each step.
  void writeStep(double time, const std::map<std::string, std::vector<double>>& nodalVectors,
                 const std::map<std::string, std::vector<double>>& nodalScalars,
                 const std::map<std::string, std::vector<double>>& elementScalars,
                 const std::map<std::string, double>& globals = {});

  // The same step written a piece at a time (rank 0 then never needs a whole field): beginStep, then
  // writeNodes for consecutive node ranges [begin, begin + count) from 0 covering every node, then endStep.
  // vectors[i]: 3 * count values of nodalVectorNames[i]; scalars[j]: count values of nodalScalarNames[j];
  // elements[e]: count values of elementScalarNames[e] given per node. endStep throws if a node was missed.
  void beginStep(double time);
  void writeNodes(std::size_t begin, std::size_t count, const std::vector<const double*>& vectors,
                  const std::vector<const double*>& scalars, const std::vector<const double*>& elements);
  void endStep(const std::map<std::string, double>& globals = {});

  // Coordinates of nodes [begin, begin + count), 3 per node (a writer made with empty coords).
  void writeCoordinates(std::size_t begin, std::size_t count, const double* xyz) const;

  int numStepsWritten() const { return step_; }
  const std::string& filename() const { return filename_; }

 private:
  void check(int status, const char* what) const;
  // Declares the variables of one kind (entityType: an ex_entity_type, e.g. EX_NODAL) and their names.
  void putCoordinates(const std::vector<double>& coords) const;
  void putCoordinateNames() const;
  void putBlocks() const;
  void forBlockNodes(std::size_t b, const std::function<void(int64_t, const std::vector<int>&)>& put) const;
  void putVariableNames(int entityType, std::vector<std::string> names, const std::string& what) const;
  void create(const std::vector<double>& coords, const std::vector<std::string>& nodalNames);
  void openToAppend(const std::vector<std::string>& nodalNames);

  std::string filename_;
  int exoid_ = -1;
  int step_ = 0;
  std::size_t numNodes_ = 0;
  bool planar_ = false;
  std::vector<std::string> vectorNames_, scalarNames_, elementNames_, globalNames_;  // globals: EX_GLOBAL
  // Nodes of one block in a row, in node order: block index b (in blockIds_), nodes [begin, end), the first
  // being element `first` (0-based) of its block. A few runs per block, not one entry per node.
  struct Run {
    std::size_t begin, end, first;
    std::size_t b;
  };
  std::vector<int> blockIds_;                // sorted distinct ids
  std::vector<char> truth_;                  // blockIds_.size() x elementNames_.size(): the block has the variable
  std::vector<std::size_t> blockSizes_;      // per block: its node count
  std::vector<Run> runs_;
  std::size_t nextNode_ = 0;                 // the step being written: nodes written so far
  bool inStep_ = false;
};

}  // namespace pf
