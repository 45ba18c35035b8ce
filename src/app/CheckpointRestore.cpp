// Restart's reading side (app/Checkpoint.hpp): rank 0 opens the checkpoint, every rank gets its small
// sections by a broadcast, and the per-point and per-bond sections reach the ranks that own the points
// chunk by chunk (ChunkedGather::scatter), so no rank holds a whole field.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>

#include "app/Checkpoint.hpp"
#include "core/InputError.hpp"
#include "parallel/Collective.hpp"

namespace pf {
namespace {

// The first differing "; "-separated piece of two fingerprint texts (a material's or a solver's parameter),
// so that the one-line message names what changed rather than two long texts.
std::pair<std::string, std::string> firstDifference(const std::string& theirs, const std::string& mine) {
  std::size_t a = 0, b = 0;
  for (;;) {
    const std::size_t ea = std::min(theirs.find("; ", a), theirs.size()), eb = std::min(mine.find("; ", b), mine.size());
    std::string pa = theirs.substr(a, ea - a), pb = mine.substr(b, eb - b);
    if (pa != pb || ea == theirs.size() || eb == mine.size()) return {pa, pb};
    a = ea + 2;
    b = eb + 2;
  }
}

// The sections every rank gets whole: what says where to go on and what the checkpoint was written for.
bool isSmall(const std::string& name) {
  for (const char* prefix : {"fingerprint/", "run/", "carry scalar/"})
    if (name.rfind(prefix, 0) == 0) return true;
  return name.rfind("output/", 0) == 0 && name.size() > 6 && name.compare(name.size() - 6, 6, "/count") == 0;
}

// One collective step of the restore: a std::runtime_error on any rank becomes "restart: 'file': why" on
// every rank (an InputError: the user gave this file).
template <class Step>
void restoreStep(const Communicator& comm, const std::string& file, Step&& step) {
  collectively(comm, [&] {
    try {
      step();
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw InputError("restart: '" + file + "': " + e.what());
    }
  });
}

std::uint64_t countOf(const CheckpointData& data, const std::string& name) {
  auto it = data.counts.find(name);
  if (it == data.counts.end()) throw std::runtime_error("lacks section '" + name + "'");
  return it->second;
}

// Collective: ncomp values per owned point from a per-point section (cloud order) into out.
void readPoints(const ChunkedGather& points, const CheckpointData& data, const std::string& name, int ncomp,
                double* out) {
  const std::uint64_t need = static_cast<std::uint64_t>(ncomp) * static_cast<std::uint64_t>(points.numGlobal());
  if (countOf(data, name) != need)
    throw std::runtime_error("section '" + name + "' has " + std::to_string(countOf(data, name)) +
                             " values, this run needs " + std::to_string(need));
  points.scatter(
      ncomp,
      [&](int begin, int count, double* chunk) {
        data.source->read(name, static_cast<std::uint64_t>(ncomp) * begin, static_cast<std::uint64_t>(ncomp) * count, chunk);
      },
      [&](int local, const double* in) { std::copy_n(in, ncomp, out + static_cast<std::size_t>(ncomp) * local); });
}

// Collective: the committed values of the per-bond history fields `names`. Each chunk of points travels as
// its bond counts, its bonds' neighbours and each field's values (the global bond order); each rank finds
// its bonds among its points' neighbours there (GlobalBondOrder::locate).
void readBonds(const ChunkedGather& points, const GlobalBondOrder& order, const CheckpointData& data,
               const std::vector<std::string>& names, Model& model) {
  const std::uint64_t total = countOf(data, "bonds/neighbors");
  if (countOf(data, "bonds/counts") != static_cast<std::uint64_t>(points.numGlobal()))
    throw std::runtime_error("it has bonds of " + std::to_string(countOf(data, "bonds/counts")) + " points, this body " +
                             std::to_string(points.numGlobal()));
  for (const std::string& name : names)
    if (countOf(data, name) != total) throw std::runtime_error("section '" + name + "' is not one value per bond");
  const BondFamily& fam = model.layout().family();
  const std::size_t nf = names.size();
  std::vector<double*> mine;  // straight into the committed arrays: no second copy of a per-bond field
  for (const std::string& name : names) mine.push_back(model.state().restoreCommitted(name.substr(6)));
  std::vector<std::size_t> where;
  std::uint64_t next = 0;  // rank 0: the chunk's first bond in the global order
  points.scatterVariable(
      static_cast<int>(1 + nf),
      [&](int begin, int count, std::vector<double>& msg) {
        msg.resize(static_cast<std::size_t>(count));
        data.source->read("bonds/counts", static_cast<std::uint64_t>(begin), static_cast<std::uint64_t>(count), msg.data());
        std::uint64_t n = 0;
        for (double c : msg) n += static_cast<std::uint64_t>(std::max(c, 0.0));
        msg.resize(static_cast<std::size_t>(count + n * (1 + nf)));
        data.source->read("bonds/neighbors", next, n, msg.data() + count);
        for (std::size_t f = 0; f < nf; ++f) data.source->read(names[f], next, n, msg.data() + count + n * (1 + f));
        next += n;
        if (begin + count == points.numGlobal() && next != total)
          throw std::runtime_error("its bond counts and neighbours disagree");
      },
      [&](int i, int width, const std::vector<const double*>& blocks) {
        order.locate(i, width, blocks[0], where);
        for (std::size_t f = 0; f < nf; ++f)
          for (std::size_t b = 0; b < where.size(); ++b) mine[f][fam.offsets[i] + b] = blocks[1 + f][where[b]];
      });
}

}  // namespace

CheckpointData loadCheckpoint(const std::string& file, const Deck& deck, const Problem& problem) {
  const std::vector<std::pair<std::string, std::string>> mine = runFingerprint(deck, problem);  // collective
  const Communicator& comm = problem.model->layout().comm();
  std::shared_ptr<const CheckpointReader> source;
  std::string small;
  collectively(comm, [&] {
    if (comm.rank() != 0) return;
    try {
      source = std::make_shared<const CheckpointReader>(file);
      small = encodeSections(source->sections(isSmall));
    } catch (const std::runtime_error& e) {
      throw InputError(std::string("restart: ") + e.what());
    }
  });
  CheckpointData data = decodeSections(comm.broadcast(small, 0));
  data.source = source;
  const std::string foreign = "restart: '" + file + "' was written for another deck: ";
  std::size_t theirs = 0;  // the same data on every rank: every rank throws the same line
  for (const auto& [name, text] : data.bytes) theirs += name.rfind("fingerprint/", 0) == 0 ? 1 : 0;
  for (const auto& [item, text] : mine) {
    auto it = data.bytes.find("fingerprint/" + item);
    if (it == data.bytes.end()) throw InputError(foreign + "it has no " + item);
    if (it->second != text) {
      const auto [there, here] = firstDifference(it->second, text);
      throw InputError(foreign + item + ": '" + there + "' there, '" + here + "' here");
    }
  }
  if (theirs != mine.size()) throw InputError(foreign + "it has more materials, blocks, solver or output lists");
  return data;
}

RestartPoint applyCheckpoint(const std::string& file, const CheckpointData& data, Problem& problem,
                             std::vector<double>& u, std::vector<double>& v) {
  Model& model = *problem.model;
  const DistributedLayout& layout = model.layout();
  const GlobalBondOrder order(layout);  // collective
  const ChunkedGather points = layout.ownedInChunks(), bondPoints = layout.ownedInChunks(order.chunkPoints());
  RestartPoint at;
  restoreStep(layout.comm(), file, [&] {
    const std::vector<double>& position = data.number("run/position");
    if (position.size() != 4) throw std::runtime_error("section 'run/position' is not 4 numbers");
    at.count = static_cast<long>(position[0]);
    at.solver = static_cast<std::size_t>(position[1]);
    at.resume.step = static_cast<long>(position[2]);
    at.resume.time = position[3];
    for (const auto& [name, values] : data.numbers)
      if (name.rfind("carry scalar/", 0) == 0 && !values.empty()) at.resume.scalars[name.substr(13)] = values[0];
  });
  const std::size_t dofs = 3 * static_cast<std::size_t>(model.numOwned());
  u.assign(dofs, 0.0);
  v.assign(dofs, 0.0);
  restoreStep(layout.comm(), file, [&] { readPoints(points, data, "node/Displacement", 3, u.data()); });
  restoreStep(layout.comm(), file, [&] { readPoints(points, data, "node/Velocity", 3, v.data()); });
  for (const auto& [name, count] : data.counts) {
    if (name.rfind("carry/", 0) != 0) continue;
    std::vector<double>& carried = at.resume.vectors[name.substr(6)];
    carried.assign(dofs, 0.0);
    restoreStep(layout.comm(), file, [&] { readPoints(points, data, name, 3, carried.data()); });
  }
  std::vector<std::string> bondFields;
  for (const StateSpec& s : model.state().specs()) {
    if (!s.history) continue;
    if (s.where != Location::Node) {
      bondFields.push_back("state/" + s.name);
      continue;
    }
    double* committed = model.state().restoreCommitted(s.name);
    restoreStep(layout.comm(), file, [&] { readPoints(points, data, "state/" + s.name, 1, committed); });
  }
  if (!bondFields.empty()) restoreStep(layout.comm(), file, [&] { readBonds(bondPoints, order, data, bondFields, model); });
  model.state().rollback();  // the committed values to trial, so the first step starts from them
  model.setCommittedDisplacement(u.data());  // collective: the committed positions, as an uninterrupted run has them
  return at;
}

}  // namespace pf
