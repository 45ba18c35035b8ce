#pragma once
// An Exodus II genesis file opened for reading, and its summary (element blocks, node sets): what the deck
// parser needs to know the mesh's node-set names and what the discretization needs to read its share of the
// elements. Every failure (missing or unreadable file, a call that fails) is an InputError naming the deck,
// "Discretization/Input Mesh File" (or the parameter given) and the file.
#include <string>
#include <vector>

namespace pf {

struct ExodusBlock {
  long long id = 0;            // the file's element-block id ("block_<id>")
  std::string type;            // element type as written, upper-cased (HEX8, TETRA, SPHERE, ...)
  long long elements = 0, nodesPerElement = 0, attributes = 0;
  long long first = 0;         // index of its first element in the file's element order
};

struct ExodusNodeSet {
  long long id = 0;
  std::string name;            // the file's name, or Peridigm's "nodelist_<id>" when it has none
  long long nodes = 0;
};

struct ExodusSummary {
  int dimension = 0;
  long long nodes = 0, elements = 0;
  std::vector<ExodusBlock> blocks;     // in file order: block k's elements follow block k-1's
  std::vector<ExodusNodeSet> nodeSets;
};

class ExodusFile {
 public:
  // inputFile: the deck (for messages); path: the resolved file name; parameter: the deck parameter that
  // names it and kind: what the file is (both for messages).
  ExodusFile(const std::string& path, const std::string& inputFile,
             const std::string& parameter = "Discretization/Input Mesh File", const std::string& kind = "mesh file");
  ~ExodusFile();
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;

  const ExodusSummary& summary() const { return summary_; }
  int id() const { return exoid_; }
  // An ExodusII return code: negative is an error (an InputError saying which call on which file).
  void check(int status, const char* call) const;
  [[noreturn]] void fail(const std::string& msg) const;  // "deck: <parameter>: <kind> 'path': msg"

 private:
  std::string path_, inputFile_, parameter_, kind_;
  int exoid_ = -1;
  ExodusSummary summary_;
};

}  // namespace pf
