#include "ExodusWriter.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace pf {

namespace {

// Peridigm files carry maximum_name_length 32; longer names would be silently truncated by
// the ExodusII library and then fail to match gold variable names, so refuse them up front.
constexpr std::size_t kMaxName = 32;

void checkName(const std::string& filename, const std::string& name) {
  if (name.empty() || name.size() > kMaxName)
    throw std::runtime_error("ExodusWriter(" + filename + "): variable name '" + name +
                             "' must have 1.." + std::to_string(kMaxName) + " characters");
}

// Every name valid and used once within its kind.
void checkNames(const std::string& filename, const std::vector<std::string>& names, const char* kind) {
  std::set<std::string> seen;
  for (const auto& n : names) {
    checkName(filename, n);
    if (!seen.insert(n).second)
      throw std::runtime_error("ExodusWriter(" + filename + "): duplicate " + kind + " variable '" + n + "'");
  }
}

std::vector<char*> cstrings(std::vector<std::string>& names) {
  std::vector<char*> out;
  for (auto& n : names) out.push_back(n.data());
  return out;
}

}  // namespace

void ExodusWriter::check(int status, const char* what) const {
  // Exodus returns negative on error and positive for warnings (e.g. name truncation).
  if (status < 0)
    throw std::runtime_error("ExodusWriter(" + filename_ + "): " + what + " failed (exodus status " +
                             std::to_string(status) + ")");
}

void ExodusWriter::putVariableNames(int entityType, std::vector<std::string> names, const std::string& what) const {
  const auto type = static_cast<ex_entity_type>(entityType);
  check(ex_put_variable_param(exoid_, type, static_cast<int>(names.size())), ("ex_put_variable_param(" + what + ")").c_str());
  auto ptrs = cstrings(names);
  check(ex_put_variable_names(exoid_, type, static_cast<int>(ptrs.size()), ptrs.data()),
        ("ex_put_variable_names(" + what + ")").c_str());
}

ExodusWriter::ExodusWriter(const std::string& filename, const std::vector<double>& coords,
                           const std::vector<int>& blockIdPerNode, bool planar,
                           const std::vector<std::string>& nodalVectorNames,
                           const std::vector<std::string>& nodalScalarNames,
                           const std::vector<std::string>& elementScalarNames,
                           const std::vector<std::string>& globalNames, bool append)
    : filename_(filename),
      numNodes_(blockIdPerNode.size()),
      planar_(planar),
      vectorNames_(nodalVectorNames),
      scalarNames_(nodalScalarNames),
      elementNames_(elementScalarNames),
      globalNames_(globalNames) {
  if (coords.size() != 3 * numNodes_)
    throw std::runtime_error("ExodusWriter(" + filename + "): coords has " + std::to_string(coords.size()) +
                             " entries, expected 3 * " + std::to_string(numNodes_));
  if (numNodes_ == 0) throw std::runtime_error("ExodusWriter(" + filename + "): no nodes");

  std::vector<std::string> nodalNames;
  for (const auto& v : vectorNames_)
    for (const char* c : {"X", "Y", "Z"}) nodalNames.push_back(v + c);
  for (const auto& s : scalarNames_) nodalNames.push_back(s);
  checkNames(filename, nodalNames, "nodal");
  checkNames(filename, elementNames_, "element");
  checkNames(filename, globalNames_, "global");

  for (int b : blockIdPerNode) {
    if (b < 1) throw std::runtime_error("ExodusWriter(" + filename + "): block ids must be >= 1");
  }
  blockIds_ = blockIdPerNode;
  std::sort(blockIds_.begin(), blockIds_.end());
  blockIds_.erase(std::unique(blockIds_.begin(), blockIds_.end()), blockIds_.end());
  blockNodes_.resize(blockIds_.size());
  for (std::size_t n = 0; n < numNodes_; ++n) {
    auto it = std::lower_bound(blockIds_.begin(), blockIds_.end(), blockIdPerNode[n]);
    blockNodes_[it - blockIds_.begin()].push_back(n);
  }

  if (append)
    openToAppend(nodalNames);
  else
    create(coords, nodalNames);
}

void ExodusWriter::create(const std::vector<double>& coords, const std::vector<std::string>& nodalNames) {
  // Peridigm's gold files are netCDF-3 64-bit-offset with 8-byte reals; match that so that
  // tools reading either file see the same format.
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  exoid_ = ex_create(filename_.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &cpuWordSize, &ioWordSize);
  if (exoid_ < 0)
    throw std::runtime_error("ExodusWriter: cannot create Exodus file '" + filename_ + "'");

  try {
    const auto nn = static_cast<int64_t>(numNodes_);
    check(ex_put_init(exoid_, "Periforge", 3, nn, nn, static_cast<int64_t>(blockIds_.size()), 0, 0),
          "ex_put_init");

    putCoordinates(coords);
    putBlocks();
    if (!nodalNames.empty()) putVariableNames(EX_NODAL, nodalNames, "nodal");
    if (!elementNames_.empty()) {
      putVariableNames(EX_ELEM_BLOCK, elementNames_, "element");
      std::vector<int> truth(blockIds_.size() * elementNames_.size(), 1);
      check(ex_put_truth_table(exoid_, EX_ELEM_BLOCK, static_cast<int>(blockIds_.size()),
                               static_cast<int>(elementNames_.size()), truth.data()),
            "ex_put_truth_table");
    }
    if (!globalNames_.empty()) putVariableNames(EX_GLOBAL, globalNames_, "global");
    check(ex_update(exoid_), "ex_update");
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    throw;
  }
}

// The file was written by a writer made with the same arguments (the checkpoint's fingerprint says the deck
// is the same); its variable counts are checked as a guard, then writeStep's indices hold.
void ExodusWriter::openToAppend(const std::vector<std::string>& nodalNames) {
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  exoid_ = ex_open(filename_.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  if (exoid_ < 0) throw std::runtime_error("ExodusWriter: cannot open Exodus file '" + filename_ + "' to continue it");
  try {
    for (const auto& [type, names] : {std::make_pair(EX_NODAL, nodalNames), std::make_pair(EX_ELEM_BLOCK, elementNames_),
                                      std::make_pair(EX_GLOBAL, globalNames_)}) {
      int n = 0;
      check(ex_get_variable_param(exoid_, type, &n), "ex_get_variable_param");
      if (n != static_cast<int>(names.size()))
        throw std::runtime_error("ExodusWriter(" + filename_ + "): the file to continue has other variables");
    }
    step_ = static_cast<int>(ex_inquire_int(exoid_, EX_INQ_TIME));
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    throw;
  }
}

void ExodusWriter::putCoordinates(const std::vector<double>& coords) const {
  std::vector<double> x(numNodes_), y(numNodes_), z(numNodes_);
  for (std::size_t n = 0; n < numNodes_; ++n) {
    x[n] = coords[3 * n];
    y[n] = coords[3 * n + 1];
    z[n] = coords[3 * n + 2];
  }
  check(ex_put_coord(exoid_, x.data(), y.data(), z.data()), "ex_put_coord");
  std::vector<std::string> coordNames{"X", "Y", "Z"};
  auto coordPtrs = cstrings(coordNames);
  check(ex_put_coord_names(exoid_, coordPtrs.data()), "ex_put_coord_names");
}

// Nodes keep their global order (local index = global id - 1); elements are renumbered block by block
// by Exodus, so the element number map carries the global id back.
void ExodusWriter::putBlocks() const {
  std::vector<int> nodeMap(numNodes_), elemMap;
  for (std::size_t n = 0; n < numNodes_; ++n) nodeMap[n] = static_cast<int>(n) + 1;
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    const auto& nodes = blockNodes_[b];
    check(ex_put_block(exoid_, EX_ELEM_BLOCK, blockIds_[b], "SPHERE", static_cast<int64_t>(nodes.size()), 1, 0, 0, 0),
          "ex_put_block");
    std::vector<int> conn(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      conn[i] = static_cast<int>(nodes[i]) + 1;
      elemMap.push_back(conn[i]);
    }
    check(ex_put_conn(exoid_, EX_ELEM_BLOCK, blockIds_[b], conn.data(), nullptr, nullptr), "ex_put_conn");
    const std::string name = "block_" + std::to_string(blockIds_[b]);
    check(ex_put_name(exoid_, EX_ELEM_BLOCK, blockIds_[b], name.c_str()), "ex_put_name");
  }
  check(ex_put_id_map(exoid_, EX_NODE_MAP, nodeMap.data()), "ex_put_id_map(nodes)");
  check(ex_put_id_map(exoid_, EX_ELEM_MAP, elemMap.data()), "ex_put_id_map(elements)");
}

ExodusWriter::~ExodusWriter() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusWriter::writeStep(double time, const std::map<std::string, std::vector<double>>& nodalVectors,
                             const std::map<std::string, std::vector<double>>& nodalScalars,
                             const std::map<std::string, std::vector<double>>& elementScalars,
                             const std::map<std::string, double>& globals) {
  auto lookup = [&](const std::map<std::string, std::vector<double>>& m, const std::string& name,
                    std::size_t expected, const char* kind) -> const std::vector<double>& {
    auto it = m.find(name);
    if (it == m.end())
      throw std::runtime_error("ExodusWriter(" + filename_ + "): writeStep is missing " + kind + " '" + name +
                               "'");
    if (it->second.size() != expected)
      throw std::runtime_error("ExodusWriter(" + filename_ + "): " + kind + " '" + name + "' has " +
                               std::to_string(it->second.size()) + " values, expected " +
                               std::to_string(expected));
    return it->second;
  };
  // Validate everything before touching the file so a bad call does not leave a half step.
  for (const auto& v : vectorNames_) lookup(nodalVectors, v, 3 * numNodes_, "nodal vector");
  for (const auto& s : scalarNames_) lookup(nodalScalars, s, numNodes_, "nodal scalar");
  for (const auto& e : elementNames_) lookup(elementScalars, e, numNodes_, "element scalar");
  std::vector<double> globalValues;
  for (const auto& g : globalNames_) {
    auto it = globals.find(g);
    if (it == globals.end())
      throw std::runtime_error("ExodusWriter(" + filename_ + "): writeStep is missing global '" + g + "'");
    globalValues.push_back(it->second);
  }

  const int step = step_ + 1;
  check(ex_put_time(exoid_, step, &time), "ex_put_time");

  const auto nn = static_cast<int64_t>(numNodes_);
  int var = 1;
  std::vector<double> buf(numNodes_);
  for (const auto& v : vectorNames_) {
    const auto& data = lookup(nodalVectors, v, 3 * numNodes_, "nodal vector");
    for (int c = 0; c < 3; ++c, ++var) {
      for (std::size_t n = 0; n < numNodes_; ++n) buf[n] = (planar_ && c == 2) ? 0.0 : data[3 * n + c];
      check(ex_put_var(exoid_, step, EX_NODAL, var, 1, nn, buf.data()), "ex_put_var(nodal)");
    }
  }
  for (const auto& s : scalarNames_) {
    const auto& data = lookup(nodalScalars, s, numNodes_, "nodal scalar");
    check(ex_put_var(exoid_, step, EX_NODAL, var++, 1, nn, data.data()), "ex_put_var(nodal)");
  }
  for (std::size_t e = 0; e < elementNames_.size(); ++e) {
    const auto& data = lookup(elementScalars, elementNames_[e], numNodes_, "element scalar");
    for (std::size_t b = 0; b < blockIds_.size(); ++b) {
      const auto& nodes = blockNodes_[b];
      buf.resize(nodes.size());
      for (std::size_t i = 0; i < nodes.size(); ++i) buf[i] = data[nodes[i]];
      check(ex_put_var(exoid_, step, EX_ELEM_BLOCK, static_cast<int>(e) + 1, blockIds_[b],
                       static_cast<int64_t>(nodes.size()), buf.data()),
            "ex_put_var(element)");
    }
    buf.resize(numNodes_);
  }
  if (!globalValues.empty())
    check(ex_put_var(exoid_, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(globalValues.size()), globalValues.data()),
          "ex_put_var(global)");
  // Sync every step: a run killed later still leaves a readable file with the steps so far.
  check(ex_update(exoid_), "ex_update");
  step_ = step;
}

}  // namespace pf
