#include "Checkpoint.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "core/InputError.hpp"
#include "parallel/ChunkedGather.hpp"
#include "parallel/Collective.hpp"

namespace pf {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string valuesText(const ParameterValues& p) {
  std::string out;
  for (const auto& [name, value] : p.values) out += name + " = " + number(value) + "; ";
  for (const auto& [name, value] : p.strings) out += name + " = " + value + "; ";
  return out;
}

std::string outputText(const OutputSpec& o) {
  std::string out = o.listName + ", " + (o.exodus ? "ExodusII" : "CSV only") + ", every " + number(o.frequency) +
                    " from " + number(o.firstStep) + " to " + number(o.lastStep) + ";";
  for (const std::string& var : o.variables) out += " " + var;
  for (const ProbeSpec& p : o.probes) out += "; probe " + p.name;
  for (const std::string& r : o.reactionNames) out += "; reaction " + r;
  return out;
}

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

// Per-point values in cloud order (ncomp per point) -> those of this rank's owned points.
std::vector<double> ownedPart(const std::vector<double>& global, const Model& model, int ncomp, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(ncomp);
  if (global.size() != n * static_cast<std::size_t>(model.layout().numGlobal()))
    throw std::runtime_error("section '" + name + "' has " + std::to_string(global.size()) + " values, this run needs " +
                             std::to_string(n * static_cast<std::size_t>(model.layout().numGlobal())));
  const std::vector<int>& gids = model.layout().gids();
  std::vector<double> out(n * static_cast<std::size_t>(model.numOwned()));
  for (int i = 0; i < model.numOwned(); ++i)
    for (std::size_t c = 0; c < n; ++c) out[n * i + c] = global[n * static_cast<std::size_t>(gids[i]) + c];
  return out;
}

// The committed values of every history field, per point or per bond, from the checkpoint's global orders.
void restoreHistory(const CheckpointData& data, const GlobalBondOrder& order, Model& model) {
  std::vector<std::size_t> where;  // each local bond's position in the checkpoint's bond order
  bool located = false;
  for (const StateSpec& s : model.state().specs()) {
    if (!s.history) continue;
    const std::vector<double>& all = data.number("state/" + s.name);
    if (s.where == Location::Node) {
      model.state().restoreCommitted(s.name, ownedPart(all, model, 1, "state/" + s.name));
      continue;
    }
    const std::vector<double>& neighbors = data.number("bonds/neighbors");
    if (!located) where = order.locate(data.number("bonds/counts"), neighbors);
    located = true;
    if (all.size() != neighbors.size()) throw std::runtime_error("section 'state/" + s.name + "' is not one value per bond");
    std::vector<double> mine(where.size());
    for (std::size_t b = 0; b < where.size(); ++b) mine[b] = all[where[b]];
    model.state().restoreCommitted(s.name, mine);
  }
}

// Collective: the sum of every point's reference coordinates taken in cloud order on rank 0 (in chunks,
// parallel/ChunkedGather.hpp), so it is the same number at any rank count; every rank gets it.
double coordinateSum(const Model& model) {
  const DistributedLayout& layout = model.layout();
  const std::vector<double>& x = model.coordinates();
  double sum = 0.0;
  const ChunkedGather gather(layout.comm(), layout.gids().data(), layout.numOwned(), layout.numGlobal());
  gather.gather({{[&](int i, double* out) { std::copy(&x[3 * i], &x[3 * i] + 3, out); }, 3}},
                [&](int, int count, const std::vector<const double*>& values) {
                  for (int k = 0; k < 3 * count; ++k) sum += values[0][k];
                });
  return layout.sum(sum);  // rank 0's sum plus zeros: exact
}

}  // namespace

std::vector<std::pair<std::string, std::string>> runFingerprint(const Deck& deck, const Problem& problem) {
  const Model& model = *problem.model;
  std::vector<std::pair<std::string, std::string>> items;
  items.emplace_back("points", number(model.layout().numGlobal()));
  items.emplace_back("bonds", number(model.sum(static_cast<double>(model.layout().family().numBonds()))));
  items.emplace_back("coordinate sum", number(coordinateSum(model)));
  for (const MaterialSpec& m : deck.materials)
    items.emplace_back("material '" + m.name + "'", "Material Model = " + m.entry->model + "; " + valuesText(m.values));
  for (const BlockModel& b : model.blocks())
    items.emplace_back("block " + b.name, b.materialName + ", horizon " + number(b.horizon));
  std::string history;
  for (const StateSpec& s : problem.model->state().specs())
    if (s.history) history += s.name + (s.where == Location::Node ? " (point) " : " (bond) ");
  items.emplace_back("history fields", history);
  for (const SolverSpec& s : deck.solvers)
    items.emplace_back("solver list '" + s.listName + "'", s.type + "; " + valuesText(s.options) + number(s.times.size()) +
                                                               " times from " + number(s.times.front()) + " to " +
                                                               number(s.times.back()));
  for (const OutputSpec& o : deck.outputs) items.emplace_back("output '" + o.filename + "'", outputText(o));
  return items;
}

Checkpointer::Checkpointer(const Deck& deck, Problem& problem,
                           const std::vector<std::unique_ptr<OutputManager>>& managers, long count)
    : deck_(deck),
      problem_(problem),
      managers_(managers),
      bonds_(problem.model->layout()),
      fingerprint_(runFingerprint(deck, problem)),
      count_(count) {}

void Checkpointer::onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
                          const std::vector<double>&) {
  ++count_;
  const long step = count_ - 1;  // the CSV's step column
  if (step > 0 && step % deck_.restart.frequency == 0) write(report, u, v);
}

void Checkpointer::write(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v) {
  const auto start = std::chrono::steady_clock::now();
  Model& model = *problem_.model;
  const DistributedLayout& layout = model.layout();
  CheckpointData data;  // complete on rank 0 only: the gathers leave the others' sections empty
  data.numbers["run/position"] = {static_cast<double>(count_), static_cast<double>(solver_),
                                  static_cast<double>(report.step), report.time};
  data.numbers["node/Displacement"] = layout.gatherToRoot(u.data(), 3);
  data.numbers["node/Velocity"] = layout.gatherToRoot(v.data(), 3);
  if (report.carry) {
    for (const auto& [name, values] : report.carry->vectors) data.numbers["carry/" + name] = layout.gatherToRoot(values->data(), 3);
    for (const auto& [name, value] : report.carry->scalars) data.numbers["carry scalar/" + name] = {value};
  }
  for (const StateSpec& s : model.state().specs()) {
    if (!s.history) continue;
    const double* committed = model.state().committed(s.name);
    data.numbers["state/" + s.name] = s.where == Location::Node ? layout.gatherToRoot(committed, 1)
                                                                : bonds_.gatherToRoot(committed);
  }
  data.numbers["bonds/counts"] = bonds_.counts();
  data.numbers["bonds/neighbors"] = bonds_.neighbors();
  for (const auto& [item, text] : fingerprint_) data.bytes["fingerprint/" + item] = text;
  for (const auto& m : managers_) m->saveTo(data);
  const std::string& file = deck_.restart.checkpointFile;
  collectively(layout.comm(), [&] {
    if (layout.rank() != 0) return;
    try {
      writeCheckpoint(file, data);
    } catch (const std::exception& e) {
      throw std::runtime_error(deck_.file + ": Restart/Checkpoint Filename '" + file + "': " + e.what());
    }
  });
  if (layout.rank() != 0) return;
  struct stat st {};
  ::stat(file.c_str(), &st);
  std::printf("periforge: checkpoint after step %ld (t = %g): %s, %.2f MB in %.3f s\n", count_ - 1, report.time,
              file.c_str(), static_cast<double>(st.st_size) / 1e6,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::fflush(stdout);
}

CheckpointData loadCheckpoint(const std::string& file, const Deck& deck, const Problem& problem) {
  const std::vector<std::pair<std::string, std::string>> mine = runFingerprint(deck, problem);  // collective
  CheckpointData data;
  collectively(problem.model->layout().comm(), [&] {
    try {
      data = readCheckpoint(file);
    } catch (const std::runtime_error& e) {
      throw InputError(std::string("restart: ") + e.what());
    }
    const std::string foreign = "restart: '" + file + "' was written for another deck: ";
    std::size_t theirs = 0;
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
  });
  return data;
}

RestartPoint applyCheckpoint(const std::string& file, const CheckpointData& data, Problem& problem,
                             std::vector<double>& u, std::vector<double>& v) {
  Model& model = *problem.model;
  const GlobalBondOrder order(model.layout());  // collective
  RestartPoint at;
  collectively(model.layout().comm(), [&] {
    try {
      const std::vector<double>& position = data.number("run/position");
      if (position.size() != 4) throw std::runtime_error("section 'run/position' is not 4 numbers");
      at.count = static_cast<long>(position[0]);
      at.solver = static_cast<std::size_t>(position[1]);
      at.resume.step = static_cast<long>(position[2]);
      at.resume.time = position[3];
      u = ownedPart(data.number("node/Displacement"), model, 3, "node/Displacement");
      v = ownedPart(data.number("node/Velocity"), model, 3, "node/Velocity");
      for (const auto& [name, values] : data.numbers) {
        if (name.rfind("carry/", 0) == 0) at.resume.vectors[name.substr(6)] = ownedPart(values, model, 3, name);
        if (name.rfind("carry scalar/", 0) == 0 && !values.empty()) at.resume.scalars[name.substr(13)] = values[0];
      }
      restoreHistory(data, order, model);
    } catch (const std::runtime_error& e) {
      throw InputError("restart: '" + file + "': " + e.what());
    }
  });
  model.setCommittedDisplacement(u.data());  // collective: the committed positions, as an uninterrupted run has them
  return at;
}

}  // namespace pf
