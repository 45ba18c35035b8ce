#include "Checkpoint.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <stdexcept>

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

// Collective: the sum of every point's reference coordinates taken in cloud order on rank 0 (in chunks,
// parallel/ChunkedGather.hpp), so it is the same number at any rank count; every rank gets it.
double coordinateSum(const Model& model) {
  const DistributedLayout& layout = model.layout();
  const std::vector<double>& x = model.coordinates();
  double sum = 0.0;
  const ChunkedGather gather = layout.ownedInChunks();
  gather.gather({{[&](int i, double* out) { std::copy(&x[3 * i], &x[3 * i] + 3, out); }, 3}},
                [&](int, int count, const std::vector<const double*>& values) {
                  for (int k = 0; k < 3 * count; ++k) sum += values[0][k];
                });
  return layout.sum(sum);  // rank 0's sum plus zeros: exact
}

using Sink = std::function<void(const double*, std::size_t)>;
// A section too big for one rank: its value count and the collective gather that streams it to rank 0's sink.
struct Streamed {
  std::string name;
  double count;
  std::function<void(const Sink&)> gather;
};

// The per-point and per-bond sections, in the order every rank gathers them (carry scalars go to small).
std::vector<Streamed> streamedSections(const ChunkedGather& points, const ChunkedGather& bondPoints,
                                       const GlobalBondOrder& bonds, Model& model,
                                       const StepReport& report, const std::vector<double>& u,
                                       const std::vector<double>& v, CheckpointData& small) {
  std::vector<Streamed> streamed;
  const double numGlobal = model.layout().numGlobal();
  auto fieldSection = [&](const std::string& name, const ChunkedGather::Field& field) {
    streamed.push_back({name, numGlobal * field.ncomp, [&points, field](const Sink& sink) {
                          points.gather({field}, [&](int, int count, const std::vector<const double*>& chunk) {
                            sink(chunk[0], static_cast<std::size_t>(field.ncomp) * count);
                          });
                        }});
  };
  auto pointSection = [&](const std::string& name, const double* values, int ncomp) {
    fieldSection(name, {[=](int i, double* out) { std::copy_n(values + ncomp * i, ncomp, out); }, ncomp});
  };
  auto bondSection = [&](const std::string& name, const ChunkedGather::VariableField& field) {
    streamed.push_back({name, bonds.total(), [&bondPoints, field](const Sink& sink) {
                          bondPoints.gatherVariable(field, [&](int, int, const double* chunk, std::size_t n) { sink(chunk, n); });
                        }});
  };
  pointSection("node/Displacement", u.data(), 3);
  pointSection("node/Velocity", v.data(), 3);
  if (report.carry) {
    for (const auto& [name, values] : report.carry->vectors) pointSection("carry/" + name, values->data(), 3);
    for (const auto& [name, value] : report.carry->scalars) small.numbers["carry scalar/" + name] = {value};
  }
  for (const StateSpec& s : model.state().specs()) {
    if (!s.history) continue;
    const double* committed = model.state().committed(s.name);
    if (s.where == Location::Node)
      pointSection("state/" + s.name, committed, 1);
    else
      bondSection("state/" + s.name, bonds.values(committed));
  }
  const BondFamily& fam = model.layout().family();
  fieldSection("bonds/counts", {[&fam](int i, double* out) { *out = fam.offsets[i + 1] - fam.offsets[i]; }, 1});
  bondSection("bonds/neighbors", bonds.neighbors());
  return streamed;
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
  // The deck's block groups, not model.blocks(): those are the blocks this rank owns points of, and a rank without
  // points of some block would find the file foreign alone and leave the others waiting.
  for (const BlockGroupSpec& b : deck.blocks)
    items.emplace_back("block group '" + b.name + "'", b.material + ", horizon " +
                                                          (b.horizonExpression ? "'" + b.horizonExpression->text() + "'"
                                                                               : number(b.horizon)));
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
      points_(problem.model->layout().ownedInChunks()),
      bondPoints_(problem.model->layout().ownedInChunks(bonds_.chunkPoints())),
      fingerprint_(runFingerprint(deck, problem)),
      count_(count) {}

void Checkpointer::onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
                          const std::vector<double>&) {
  ++count_;
  const long step = count_ - 1;  // the CSV's step column
  if (step > 0 && step % deck_.restart.frequency == 0) write(report, u, v);
}

// Rank 0 streams the file: small sections whole, then per-point and per-bond sections chunk by chunk as the
// gathers deliver them, so no rank holds a whole field. A failure on rank 0 (disk full) stops its writing
// but not its part in the gathers, so every rank reaches the final agreement and fails there together.
void Checkpointer::write(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v) {
  const auto start = std::chrono::steady_clock::now();
  Model& model = *problem_.model;
  const DistributedLayout& layout = model.layout();
  const bool root = layout.rank() == 0;
  CheckpointData small;  // the managers' file copies are named on rank 0 only
  small.numbers["run/position"] = {static_cast<double>(count_), static_cast<double>(solver_),
                                   static_cast<double>(report.step), report.time};
  for (const auto& [item, text] : fingerprint_) small.bytes["fingerprint/" + item] = text;
  for (const auto& m : managers_) m->saveTo(small);
  const std::vector<Streamed> streamed = streamedSections(points_, bondPoints_, bonds_, model, report, u, v, small);

  const std::string& file = deck_.restart.checkpointFile;
  std::unique_ptr<CheckpointWriter> out;
  std::exception_ptr error;
  auto guarded = [&](auto&& f) {
    if (!root || error) return;
    try {
      f();
    } catch (...) {
      error = std::current_exception();
    }
  };
  guarded([&] {
    out = std::make_unique<CheckpointWriter>(file, small.numbers.size() + small.bytes.size() + small.fileCopies.size() + streamed.size());
    out->add(small);
  });
  for (const Streamed& s : streamed) {
    guarded([&] { out->beginNumbers(s.name, static_cast<std::uint64_t>(s.count)); });
    s.gather([&](const double* values, std::size_t n) { guarded([&] { out->put(values, n); }); });
  }
  collectively(layout.comm(), [&] {
    try {
      if (error) std::rethrow_exception(error);
      if (root) out->commit();
    } catch (const std::exception& e) {
      throw std::runtime_error(deck_.file + ": Restart/Checkpoint Filename '" + file + "': " + e.what());
    }
  });
  if (!root) return;
  struct stat st {};
  ::stat(file.c_str(), &st);
  std::printf("periforge: checkpoint after step %ld (t = %g): %s, %.2f MB in %.3f s\n", count_ - 1, report.time,
              file.c_str(), static_cast<double>(st.st_size) / 1e6,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::fflush(stdout);
}

}  // namespace pf
