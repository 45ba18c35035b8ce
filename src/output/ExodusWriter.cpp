#include "ExodusWriter.hpp"

#include <exodusII.h>

#include <algorithm>
#include <functional>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace pf {

namespace {

// Peridigm files carry maximum_name_length 32; longer names would be silently truncated by
// the ExodusII library and then fail to match gold variable names, so refuse them up front.
constexpr std::size_t kMaxName = 32;

// Coordinates and the node map go to the file in pieces of this many nodes (a bounded copy, not a whole one).
constexpr std::size_t kPiece = 32768;

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

void BlockRuns::add(const int* ids, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k, ++numNodes_) {
    if (runs_.empty() || runs_.back().id != ids[k]) runs_.push_back({numNodes_, numNodes_, ids[k]});
    runs_.back().end = numNodes_ + 1;
  }
}

ExodusWriter::ExodusWriter(const std::string& filename, const std::vector<double>& coords, const BlockRuns& blocks,
                           bool planar, const std::vector<std::string>& nodalVectorNames,
                           const std::vector<std::string>& nodalScalarNames,
                           const std::vector<std::string>& elementScalarNames,
                           const std::vector<std::string>& globalNames, bool append,
                           const std::map<int, std::vector<char>>& elementVariablesOf)
    : filename_(filename),
      numNodes_(blocks.numNodes()),
      planar_(planar),
      vectorNames_(nodalVectorNames),
      scalarNames_(nodalScalarNames),
      elementNames_(elementScalarNames),
      globalNames_(globalNames) {
  if (!coords.empty() && coords.size() != 3 * numNodes_)
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

  for (const BlockRuns::Run& r : blocks.runs()) {  // the distinct ids, sorted
    if (r.id < 1) throw std::runtime_error("ExodusWriter(" + filename + "): block ids must be >= 1");
    const auto at = std::lower_bound(blockIds_.begin(), blockIds_.end(), r.id);
    if (at == blockIds_.end() || *at != r.id) blockIds_.insert(at, r.id);
  }  truth_.assign(blockIds_.size() * elementNames_.size(), 1);
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    const auto it = elementVariablesOf.find(blockIds_[b]);
    if (it == elementVariablesOf.end()) continue;
    if (it->second.size() != elementNames_.size())
      throw std::logic_error("ExodusWriter(" + filename + "): a block's element-variable flags do not match the names");
    for (std::size_t e = 0; e < elementNames_.size(); ++e) truth_[b * elementNames_.size() + e] = it->second[e] ? 1 : 0;
  }

  blockSizes_.assign(blockIds_.size(), 0);
  for (const BlockRuns::Run& r : blocks.runs()) {
    const auto b = static_cast<std::size_t>(std::lower_bound(blockIds_.begin(), blockIds_.end(), r.id) - blockIds_.begin());
    runs_.push_back({r.begin, r.end, blockSizes_[b], b});
    blockSizes_[b] += r.end - r.begin;
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

    if (!coords.empty()) putCoordinates(coords);
    putCoordinateNames();
    putBlocks();
    if (!nodalNames.empty()) putVariableNames(EX_NODAL, nodalNames, "nodal");
    if (!elementNames_.empty()) {
      putVariableNames(EX_ELEM_BLOCK, elementNames_, "element");
      std::vector<int> truth(truth_.begin(), truth_.end());
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

// In pieces of kPiece nodes, so that no whole-cloud copy is made beside the caller's arrays.
void ExodusWriter::putCoordinates(const std::vector<double>& coords) const {
  for (std::size_t begin = 0; begin < numNodes_; begin += kPiece)
    writeCoordinates(begin, std::min(kPiece, numNodes_ - begin), &coords[3 * begin]);
}

void ExodusWriter::writeCoordinates(std::size_t begin, std::size_t count, const double* xyz) const {
  if (begin + count > numNodes_)
    throw std::runtime_error("ExodusWriter(" + filename_ + "): coordinates of nodes past " + std::to_string(numNodes_));
  std::vector<double> x(count), y(count), z(count);
  for (std::size_t n = 0; n < count; ++n) {
    x[n] = xyz[3 * n];
    y[n] = xyz[3 * n + 1];
    z[n] = xyz[3 * n + 2];
  }
  check(ex_put_partial_coord(exoid_, static_cast<int64_t>(begin) + 1, static_cast<int64_t>(count), x.data(), y.data(),
                             z.data()),
        "ex_put_partial_coord");
}

void ExodusWriter::putCoordinateNames() const {
  std::vector<std::string> coordNames{"X", "Y", "Z"};
  auto coordPtrs = cstrings(coordNames);
  check(ex_put_coord_names(exoid_, coordPtrs.data()), "ex_put_coord_names");
}

// Block b's nodes in node order as 1-based ids, to put(first, ids) in pieces of at most kPiece; first: the
// 1-based position of the piece's first element in the block.
void ExodusWriter::forBlockNodes(std::size_t b, const std::function<void(int64_t, const std::vector<int>&)>& put) const {
  std::vector<int> ids;
  int64_t first = 1;
  for (const Run& r : runs_) {
    if (r.b != b) continue;
    for (std::size_t n = r.begin; n < r.end; ++n) {
      ids.push_back(static_cast<int>(n) + 1);
      if (ids.size() < kPiece) continue;
      put(first, ids);
      first += static_cast<int64_t>(ids.size());
      ids.clear();
    }
  }
  if (!ids.empty()) put(first, ids);
}

// Nodes keep their global order (local index = global id - 1); elements are renumbered block by block
// by Exodus, so the element number map carries the global id back. Everything in pieces of kPiece entries,
// so no per-node list is made.
void ExodusWriter::putBlocks() const {
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    check(ex_put_block(exoid_, EX_ELEM_BLOCK, blockIds_[b], "SPHERE", static_cast<int64_t>(blockSizes_[b]), 1, 0, 0, 0),
          "ex_put_block");
    forBlockNodes(b, [&](int64_t first, const std::vector<int>& ids) {
      check(ex_put_partial_elem_conn(exoid_, blockIds_[b], first, static_cast<int64_t>(ids.size()), ids.data()),
            "ex_put_partial_elem_conn");
    });
    const std::string name = "block_" + std::to_string(blockIds_[b]);
    check(ex_put_name(exoid_, EX_ELEM_BLOCK, blockIds_[b], name.c_str()), "ex_put_name");
  }
  // The node map, then the element map (the order the file's variables are defined in).
  std::vector<int> ids;
  for (std::size_t begin = 0; begin < numNodes_; begin += kPiece) {
    const std::size_t count = std::min(kPiece, numNodes_ - begin);
    ids.resize(count);
    for (std::size_t n = 0; n < count; ++n) ids[n] = static_cast<int>(begin + n) + 1;
    check(ex_put_partial_id_map(exoid_, EX_NODE_MAP, static_cast<int64_t>(begin) + 1, static_cast<int64_t>(count),
                                ids.data()),
          "ex_put_partial_id_map(nodes)");
  }
  int64_t blockStart = 0;  // elements before block b
  for (std::size_t b = 0; b < blockIds_.size(); ++b) {
    forBlockNodes(b, [&](int64_t first, const std::vector<int>& piece) {
      check(ex_put_partial_id_map(exoid_, EX_ELEM_MAP, blockStart + first, static_cast<int64_t>(piece.size()), piece.data()),
            "ex_put_partial_id_map(elements)");
    });
    blockStart += static_cast<int64_t>(blockSizes_[b]);
  }
}

ExodusWriter::~ExodusWriter() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusWriter::writeStep(double time, const std::map<std::string, std::vector<double>>& nodalVectors,
                             const std::map<std::string, std::vector<double>>& nodalScalars,
                             const std::map<std::string, std::vector<double>>& elementScalars,
                             const std::map<std::string, double>& globals) {
  auto lookup = [&](const std::map<std::string, std::vector<double>>& m, const std::string& name,
                    std::size_t expected, const char* kind) -> const double* {
    auto it = m.find(name);
    if (it == m.end())
      throw std::runtime_error("ExodusWriter(" + filename_ + "): writeStep is missing " + kind + " '" + name +
                               "'");
    if (it->second.size() != expected)
      throw std::runtime_error("ExodusWriter(" + filename_ + "): " + kind + " '" + name + "' has " +
                               std::to_string(it->second.size()) + " values, expected " +
                               std::to_string(expected));
    return it->second.data();
  };
  // Validate everything before touching the file so a bad call does not leave a half step.
  std::vector<const double*> vectors, scalars, elements;
  for (const auto& v : vectorNames_) vectors.push_back(lookup(nodalVectors, v, 3 * numNodes_, "nodal vector"));
  for (const auto& s : scalarNames_) scalars.push_back(lookup(nodalScalars, s, numNodes_, "nodal scalar"));
  for (const auto& e : elementNames_) elements.push_back(lookup(elementScalars, e, numNodes_, "element scalar"));
  for (const auto& g : globalNames_)
    if (globals.find(g) == globals.end())
      throw std::runtime_error("ExodusWriter(" + filename_ + "): writeStep is missing global '" + g + "'");
  beginStep(time);
  writeNodes(0, numNodes_, vectors, scalars, elements);
  endStep(globals);
}

void ExodusWriter::beginStep(double time) {
  if (inStep_) throw std::logic_error("ExodusWriter(" + filename_ + "): beginStep inside a step");
  const int step = step_ + 1;
  check(ex_put_time(exoid_, step, &time), "ex_put_time");
  inStep_ = true;
  nextNode_ = 0;
}

void ExodusWriter::writeNodes(std::size_t begin, std::size_t count, const std::vector<const double*>& vectors,
                              const std::vector<const double*>& scalars, const std::vector<const double*>& elements) {
  if (!inStep_ || begin != nextNode_ || begin + count > numNodes_ || vectors.size() != vectorNames_.size() ||
      scalars.size() != scalarNames_.size() || elements.size() != elementNames_.size())
    throw std::logic_error("ExodusWriter(" + filename_ + "): writeNodes out of order or with other fields");
  const int step = step_ + 1;
  const auto first = static_cast<int64_t>(begin) + 1, nn = static_cast<int64_t>(count);
  int var = 1;
  std::vector<double> buf(count);
  for (const double* data : vectors)
    for (int c = 0; c < 3; ++c, ++var) {
      for (std::size_t n = 0; n < count; ++n) buf[n] = (planar_ && c == 2) ? 0.0 : data[3 * n + c];
      check(ex_put_partial_var(exoid_, step, EX_NODAL, var, 1, first, nn, buf.data()), "ex_put_partial_var(nodal)");
    }
  for (const double* data : scalars)
    check(ex_put_partial_var(exoid_, step, EX_NODAL, var++, 1, first, nn, data), "ex_put_partial_var(nodal)");
  // Element values: each run's share of [begin, begin + count) is a contiguous piece of its block.
  for (const Run& r : runs_) {
    const std::size_t lo = std::max(r.begin, begin), hi = std::min(r.end, begin + count);
    if (lo >= hi) continue;
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (truth_[r.b * elements.size() + e])
        check(ex_put_partial_var(exoid_, step, EX_ELEM_BLOCK, static_cast<int>(e) + 1, blockIds_[r.b],
                               static_cast<int64_t>(r.first + (lo - r.begin)) + 1, static_cast<int64_t>(hi - lo),
                               elements[e] + (lo - begin)),
            "ex_put_partial_var(element)");
  }
  nextNode_ = begin + count;
}

void ExodusWriter::endStep(const std::map<std::string, double>& globals) {
  if (!inStep_ || nextNode_ != numNodes_)
    throw std::logic_error("ExodusWriter(" + filename_ + "): endStep before every node was written");
  std::vector<double> globalValues;
  for (const auto& g : globalNames_) {
    auto it = globals.find(g);
    if (it == globals.end())
      throw std::runtime_error("ExodusWriter(" + filename_ + "): endStep is missing global '" + g + "'");
    globalValues.push_back(it->second);
  }
  const int step = step_ + 1;
  if (!globalValues.empty())
    check(ex_put_var(exoid_, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(globalValues.size()), globalValues.data()),
          "ex_put_var(global)");
  // Sync every step: a run killed later still leaves a readable file with the steps so far.
  check(ex_update(exoid_), "ex_update");
  step_ = step;
  inStep_ = false;
}

}  // namespace pf
