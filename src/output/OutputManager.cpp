#include "OutputManager.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "CheckpointFile.hpp"
#include "ExodusWriter.hpp"
#include "core/OutputFields.hpp"
#include "HistoryWriter.hpp"
#include "OutputFiles.hpp"
#include "core/InputError.hpp"
#include "solvers/Solver.hpp"
#include "parallel/ChunkedGather.hpp"
#include "parallel/Collective.hpp"

namespace pf {
namespace {

// Peridigm requests "Element_Id" but writes the variable as "ID"; exodiff against its gold files needs the same.
std::string exodusName(const std::string& var) { return var == "Element_Id" ? "ID" : var; }

}  // namespace

OutputManager::OutputManager(const OutputSpec& out, const Deck& deck, Problem& problem)
    : pb_(problem), model_(*problem.model), inputFile_(deck.file) {
  exodus_ = out.exodus;
  baseName_ = out.filename;
  exodusName_ = out.filename + ".e";
  historyName_ = out.filename + ".csv";
  where_ = deck.file + ": " + out.listName + "/Output Filename '" + out.filename + "'";
  frequency_ = out.frequency;
  first_ = out.firstStep;
  last_ = out.lastStep;
  for (const std::string& var : out.variables) {
    const auto compute = std::find_if(deck.computes.begin(), deck.computes.end(),
                                      [&](const ComputeSpec& c) { return c.label == var; });
    if (compute != deck.computes.end()) {
      addCompute(*compute);
      continue;
    }
    if (isGlobalField(var)) {
      requireGlobal(var, out.listName + "/Output Variables");
      globals_.push_back(var);
      continue;
    }
    if (isTensorField(var)) {
      addTensor(var, out.listName + "/Output Variables");
      continue;
    }
    if (isMaterialVectorField(var)) {
      for (const char* c : {"X", "Y", "Z"}) requireComputed(var + c, out.listName + "/Output Variables");
      nodalVectors_.push_back(var);
      continue;
    }
    requireComputed(var, out.listName + "/Output Variables");
    const std::vector<std::string> fieldOutputs = model_.fields().outputs();
    if (std::find(fieldOutputs.begin(), fieldOutputs.end(), var) != fieldOutputs.end()) nodalScalars_.push_back(var);
    else (isCoreVectorField(var) ? nodalVectors_ : elementScalars_).push_back(var);
  }
  findElementVariablesOfBlocks();
  for (const ProbeSpec& p : out.probes) probes_.push_back(locateProbe(p, out.listName));
  addReactions(out);
  applied_ = out.appliedDisplacement;
  bodyForce_.assign(model_.numDofs(), 0.0);
  if (exodus_)
    gather_ = std::make_unique<ChunkedGather>(model_.layout().ownedInChunks());
  gatherBlockIds();
  onRoot([&] { openFiles(); });
  blockRuns_ = BlockRuns();
  writeCoordinates();
}

bool OutputManager::dummyNodeFile() const {
  return nodalVectors_.empty() && nodalScalars_.empty() && elementScalars_.empty() &&
         (!globals_.empty() || !computes_.empty());
}

// Collective: rank 0 gets every point's block in cloud order, for the Exodus file's element blocks, as runs of
// points of one block (chunk by chunk: no per-point list; a few runs per block).
void OutputManager::gatherBlockIds() {
  if (!gather_ || dummyNodeFile()) return;
  std::vector<ChunkedGather::Field> fields = {{[&](int i, double* out) {
                                                 for (const BlockModel& b : model_.blocks())
                                                   if (i >= b.begin && i < b.end) *out = b.blockId;
                                               },
                                               1}};
  onRoot(
      [&] {
        std::vector<int> ids;
        gather_->gather(fields, [&](int, int count, const std::vector<const double*>& values) {
          ids.assign(values[0], values[0] + count);
          blockRuns_.add(ids.data(), ids.size());
        });
      },
      true);
}

// Collective: the new Exodus file's coordinates, chunk by chunk as the ranks send them.
void OutputManager::writeCoordinates() {
  if (!gather_ || dummyNodeFile()) return;
  const std::vector<double>& x = model_.coordinates();
  onRoot(
      [&] {
        gather_->gather({{[&](int i, double* out) { std::copy(&x[3 * i], &x[3 * i] + 3, out); }, 3}},
                        [&](int begin, int count, const std::vector<const double*>& values) {
                          writer_->writeCoordinates(begin, count, values[0]);
                        });
      },
      true);
}

// Collective: rank 0 runs write; its failure (a full disk, a missing directory) becomes every rank's error,
// naming the deck and the output list.
// everyRank: every rank runs write (a collective write, rank 0 writing the file).
void OutputManager::onRoot(const std::function<void()>& write, bool everyRank) {
  const bool root = model_.layout().rank() == 0;
  collectively(model_.layout().comm(), [&] {
    if (!root && !everyRank) return;
    try {
      write();
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      const std::string what = e.what();
      throw std::runtime_error(what.rfind(where_, 0) == 0 ? what : where_ + ": " + what);
    }
  });
}

// Rank 0: the lock first (a second run on the name must not touch the first one's parts), then the writers.
void OutputManager::openFiles() {
  files_ = std::make_unique<OutputFiles>(baseName_, exodus_ ? std::vector<std::string>{".csv", ".e"}
                                                            : std::vector<std::string>{".csv"}, where_);
  try {
    openWriters(false);
  } catch (const std::exception& e) {
    files_->abandon(std::string("failed before the first step: ") + e.what());
    throw;
  }
}

// The history's columns, on every rank (the finite check names them).
std::vector<std::string> OutputManager::historyColumns() const {
  std::vector<std::string> cols = {"time", "step"};
  if (applied_) cols.push_back("Applied_Displacement");
  auto label = [](std::string s) {
    std::replace(s.begin(), s.end(), ' ', '_');
    return s;
  };
  for (const Reaction& r : reactions_)
    for (const char* c : {"X", "Y", "Z"}) cols.push_back("Reaction_" + label(r.label) + "_" + c);
  for (const RigidWall& w : model_.rigidWalls())
    for (const char* c : {"X", "Y", "Z"}) cols.push_back("Reaction_" + label(w.name) + "_" + c);
  const std::vector<std::string> terms = model_.termHistoryNames();
  cols.insert(cols.end(), terms.begin(), terms.end());
  for (const Probe& p : probes_)
    for (const std::string& var : p.variables) {
      if (isCoreVectorField(var))
        for (const char* c : {"X", "Y", "Z"}) cols.push_back("Probe_" + label(p.name) + "_" + var + c);
      else
        cols.push_back("Probe_" + label(p.name) + "_" + var);
    }
  const std::vector<std::string> computed = computes_.names();
  cols.insert(cols.end(), computed.begin(), computed.end());
  return cols;
}

// The history's columns, and the Exodus file's variables.
void OutputManager::openWriters(bool append) {
  history_ = std::make_unique<HistoryWriter>(files_->part(".csv"), historyColumns(), append);
  if (!exodus_) return;
  const std::vector<std::string> computed = computes_.names();
  std::vector<std::string> scalars = nodalScalars_, elements, globals = globals_;
  for (const std::string& var : elementScalars_) elements.push_back(exodusName(var));
  globals.insert(globals.end(), computed.begin(), computed.end());
  if (dummyNodeFile())
    // Peridigm's file for global data only: one dummy node at the origin in one one-element block.
    writer_ = std::make_unique<ExodusWriter>(files_->part(".e"), std::vector<double>{0.0, 0.0, 0.0}, std::vector<int>{1},
                                             false, nodalVectors_, scalars, elements, globals, append);
  else
    writer_ = std::make_unique<ExodusWriter>(files_->part(".e"), std::vector<double>{}, blockRuns_, pb_.cloud.planar,
                                             nodalVectors_, scalars, elements, globals, append, elementVariablesOf_);
}

OutputManager::~OutputManager() = default;

double OutputManager::termValue(const std::string& name, int k) const {
  const std::vector<double>* term = model_.termOutput(name);
  return term ? (*term)[k] : 0.0;
}

double OutputManager::nodeValue(const std::string& var, int comp, int i, const std::vector<double>& u,
                                const std::vector<double>& v, const std::vector<double>& f) const {
  const std::vector<double>& x = model_.coordinates();
  if (var == "Displacement") return u[3 * i + comp];
  if (var == "Velocity") return v[3 * i + comp];
  if (var == "Force_Density") return f[3 * i + comp];
  if (var == "Force") return f[3 * i + comp] * model_.volume()[i];
  // bodyForce_ holds b at the step's time (onStep fills it first) or zeros.
  if (var == "Acceleration")  // the model's force terms (contact) included, as Peridigm's
    return (f[3 * i + comp] + termValue("Contact_Force_Density", 3 * i + comp) + bodyForce_[3 * i + comp]) /
           model_.density()[i];
  if (var == "Contact_Force_Density") return termValue(var, 3 * i + comp);  // 0 without contact
  if (var == "Kinetic_Energy")  // Peridigm's per-point compute: 1/2 rho V |v|^2
    return 0.5 * model_.density()[i] * model_.volume()[i] *
           (v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
  if (var == "Model_Coordinates") return x[3 * i + comp];
  if (var == "External_Force_Density") return bodyForce_[3 * i + comp];  // Peridigm's name for the body force b
  if (var == "Coordinates") return x[3 * i + comp] + u[3 * i + comp];
  if (var == "Weighted_Volume") return model_.weightedVolume()[i];
  if (var == "Element_Id") return model_.layout().gids()[i] + 1;
  if (var == "Proc_Num") return model_.layout().rank();
  if (var == "Number_Of_Neighbors") return model_.numNeighbors(i);
  // Damage: set by the kernels of blocks with a damage model; 0 where nothing can break (as Peridigm).
  if (var == "Damage") return model_.state().has("Damage") ? model_.state().committed("Damage")[i] : 0.0;
  if (var == "Volume") return model_.volume()[i];
  if (var == "Radius") return std::cbrt(3.0 * model_.volume()[i] / (4.0 * M_PI));  // Peridigm's: the sphere of the volume
  if (var == "Horizon")  // the node's own horizon (its block's, or the block's expression at the node)
    for (const BlockModel& b : model_.blocks())
      if (i >= b.begin && i < b.end) return model_.horizonOf(i, b);
  // A variable some block's material computes (requireComputed) and this rank's blocks do not: 0, as at np 1
  // for the points of the other materials.
  if (isMaterialVectorField(var)) {
    const std::string c = var + "XYZ"[comp];
    return model_.state().has(c) ? model_.state().committed(c)[i] : 0.0;
  }
  return model_.state().has(var) ? model_.state().committed(var)[i] : 0.0;
}

void OutputManager::onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
                           const std::vector<double>& f) {
  ++count_;
  nonlinearIterations_ += report.nonlinearIterations;  // every step counts, written or not
  lastStep_ = count_ - 1;
  lastTime_ = report.time;
  wroteExodus_ = false;
  const long every = static_cast<long>(report.outputEvery > 0 ? report.outputEvery : frequency_) * report.outputEveryFactor;
  if (count_ < first_ || (last_ > 0 && count_ > last_ + 1) || (count_ - 1) % every != 0) return;
  const std::vector<double> global = historyRow(report, u, v, f);
  std::vector<double> row = {report.time, static_cast<double>(count_ - 1)};
  if (applied_) row.push_back((*applied_)(0.0, 0.0, 0.0, report.time));
  row.insert(row.end(), global.begin(), global.end());
  // Every rank holds the reduced row: all agree without a message, and nothing non-finite is written.
  for (std::size_t k = 0; k < row.size(); ++k)  // the columns' names are built only for the message
    if (!std::isfinite(row[k])) throw nonFinite(historyColumns()[k], "history column", row[k]);
  onRoot([&] { history_->writeRow(row); });
  if (exodus_) writeExodusStep(report.time, u, v, f);
  wroteExodus_ = exodus_;
}

// Collective: reactions and probes reduced over ranks; fills bodyForce_ at the step's time first (a probe lives on one rank, others add 0).
std::vector<double> OutputManager::historyRow(const StepReport& report, const std::vector<double>& u,
                                              const std::vector<double>& v, const std::vector<double>& f) {
  std::vector<double> local;
  if (model_.hasBodyForce()) model_.bodyForce(report.time, bodyForce_.data());
  for (const Reaction& r : reactions_)
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int i : r.nodes) s -= (f[3 * i + c] + bodyForce_[3 * i + c]) * model_.volume()[i];
      local.push_back(s);
    }
  // A rigid wall's force on the body in the step just taken (model/RigidWall.hpp).
  local.insert(local.end(), model_.wallReactions().begin(), model_.wallReactions().end());
  const std::vector<double> terms = model_.termHistoryShares();  // contact: each block pair's force
  local.insert(local.end(), terms.begin(), terms.end());
  for (const Probe& p : probes_)
    for (const std::string& var : p.variables) {
      const int ncomp = isCoreVectorField(var) ? 3 : 1;
      for (int c = 0; c < ncomp; ++c) local.push_back(p.local >= 0 ? nodeValue(var, c, p.local, u, v, f) : 0.0);
    }
  std::vector<double> global(local.size());
  if (!local.empty()) model_.layout().comm().sum(local.data(), global.data(), static_cast<int>(local.size()));
  if (!computes_.empty()) {
    computeValues_ = computes_.evaluate(model_.layout().comm(),
                                        [&](const std::string& var, int c, int i) { return nodeValue(var, c, i, u, v, f); });
    global.insert(global.end(), computeValues_.begin(), computeValues_.end());
  }
  return global;
}

// Collective: rank 0 writes the fields as they arrive, a chunk at a time.
void OutputManager::writeExodusStep(double time, const std::vector<double>& u, const std::vector<double>& v,
                                    const std::vector<double>& f) {
  std::map<std::string, double> globals;
  for (const std::string& var : globals_) {
    double e = 0.0;
    if (var == "Nonlinear_Solver_Iterations") {  // the same on every rank: not summed
      globals[var] = static_cast<double>(nonlinearIterations_);
      continue;
    }
    if (var == "Global_Contact_Energy") {
      e = model_.termEnergy();
    } else if (var == "Global_Heat") {  // sum rho c (T - T_start) V
      std::vector<double> c(static_cast<std::size_t>(model_.numOwned()));
      model_.fieldCapacity("Temperature", c.data());
      const double* change = model_.state().committed("Temperature_Change");
      for (int i = 0; i < model_.numOwned(); ++i) e += c[i] * change[i] * model_.volume()[i];
    } else if (const char* field = globalSourceField(var)) {  // a node field of energies per node, summed
      const double* per = model_.state().committed(field);
      for (int i = 0; i < model_.numOwned(); ++i) e += per[i];
    } else {  // Global_Kinetic_Energy = sum 1/2 rho V |v|^2
      for (int i = 0; i < model_.numOwned(); ++i)
        e += 0.5 * model_.density()[i] * model_.volume()[i] *
             (v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
    }
    globals[var] = model_.sum(e);
  }
  const std::vector<std::string> computed = computes_.names();
  for (std::size_t k = 0; k < computed.size(); ++k) globals[computed[k]] = computeValues_[k];
  for (const auto& [var, value] : globals)  // reduced: the same on every rank
    if (!std::isfinite(value)) throw nonFinite(var, "global variable", value);
  // Rank 0 writes the fields chunk by chunk in cloud order as the ranks send their points' values, taken
  // straight from the model (parallel/ChunkedGather.hpp): no rank copies a whole field, not even its share.
  std::vector<ChunkedGather::Field> fields;
  for (const std::string& var : nodalVectors_)
    fields.push_back({[&, var](int i, double* out) { for (int c = 0; c < 3; ++c) out[c] = nodeValue(var, c, i, u, v, f); }, 3});
  for (const std::string& var : nodalScalars_)
    fields.push_back({[&, var](int i, double* out) { *out = nodeValue(var, 0, i, u, v, f); }, 1});
  if (!kinematic_.empty()) model_.kinematicTensors(u.data(), F_.data(), Kinv_.data());
  for (const std::string& var : elementScalars_) {
    const auto k = kinematic_.find(var);
    if (k != kinematic_.end()) {
      const double* a = k->second.first->data();
      const int c = k->second.second;
      fields.push_back({[a, c](int i, double* out) { *out = a[9 * i + c]; }, 1});
      continue;
    }
    fields.push_back({[&, stored = storedComponent(var)](int i, double* out) { *out = nodeValue(stored, 0, i, u, v, f); }, 1});
  }
  if (fields.empty()) {  // globals only: Peridigm's one-dummy-node file
    onRoot([&] { writer_->writeStep(time, {}, {}, {}, globals); });
    return;
  }
  const std::size_t nv = nodalVectors_.size(), ns = nv + nodalScalars_.size();
  const int numGlobal = gather_->numGlobal();
  std::string bad;  // rank 0: the first non-finite field value of the step, described (the .e stays a .part)
  onRoot(
      [&] {
        gather_->gather(fields, [&](int begin, int count, const std::vector<const double*>& values) {
          if (bad.empty()) bad = firstNonFinite(begin, count, values);
          if (begin == 0) writer_->beginStep(time);
          writer_->writeNodes(begin, count, {values.begin(), values.begin() + nv}, {values.begin() + nv, values.begin() + ns},
                              {values.begin() + ns, values.end()});
          if (begin + count == numGlobal) writer_->endStep(globals);
        });
      },
      true);
  bad = model_.layout().comm().broadcast(bad, 0);
  if (!bad.empty()) throw SolverFailure("output '" + exodusName_ + "': non-finite " + bad + stepText());
}

// Rank 0, one gathered chunk: "<variable> (<value>) at point <id>" of the first non-finite value, or "".
std::string OutputManager::firstNonFinite(int begin, int count, const std::vector<const double*>& values) const {
  std::vector<std::pair<const std::string*, int>> vars;  // in the order of the gathered fields
  for (const std::string& var : nodalVectors_) vars.emplace_back(&var, 3);
  for (const std::string& var : nodalScalars_) vars.emplace_back(&var, 1);
  for (const std::string& var : elementScalars_) vars.emplace_back(&var, 1);
  for (std::size_t k = 0; k < vars.size(); ++k)
    for (int i = 0; i < count * vars[k].second; ++i)
      if (!std::isfinite(values[k][i])) {
        std::ostringstream s;
        s << *vars[k].first << " (" << values[k][i] << ") at point " << begin + i / vars[k].second + 1
          << " (Element_Id)";
        return s.str();
      }
  return "";
}

// " at step <n> (t = <t>)" of the step being written.
std::string OutputManager::stepText() const {
  std::ostringstream s;
  s << " at step " << count_ - 1 << " (t = " << lastTime_ << ")";
  return s.str();
}

SolverFailure OutputManager::nonFinite(const std::string& var, const char* kind, double value) const {
  std::ostringstream s;
  s << "output '" << baseName_ << "': " << kind << " " << var << " is " << value << stepText()
    << " (a value beyond double precision's range, about 1.8e308): nothing non-finite is written";
  return SolverFailure(s.str());
}

void OutputManager::saveTo(CheckpointData& data) const {
  const std::string key = "output/" + baseName_ + "/";
  data.numbers[key + "count"] = {static_cast<double>(count_), lastTime_, static_cast<double>(nonlinearIterations_)};
  if (!files_) return;  // not rank 0
  data.fileCopies[key + "csv"] = files_->part(".csv");
  if (exodus_) data.fileCopies[key + "exodus"] = files_->part(".e");
}

void OutputManager::resumeFrom(const CheckpointData& data) {
  const std::string key = "output/" + baseName_ + "/";
  const std::vector<double>& count = data.number(key + "count");
  count_ = static_cast<long>(count.at(0));
  lastStep_ = count_ - 1;
  lastTime_ = count.at(1);
  nonlinearIterations_ = count.size() > 2 ? static_cast<long>(count[2]) : 0;  // checkpoints before it: 0
  gatherBlockIds();
  onRoot([&] {
    writer_.reset();
    history_.reset();
    if (!data.source) throw std::logic_error("OutputManager::resumeFrom: rank 0 needs the checkpoint file");
    for (const auto& [suffix, section] : {std::make_pair(".csv", "csv"), std::make_pair(".e", "exodus")}) {
      if (suffix == std::string(".e") && !exodus_) continue;
      data.source->copyTo(key + section, files_->part(suffix));
    }
    openWriters(true);
    std::string header;
    for (const std::string& c : history_->columns()) header += (header.empty() ? "" : ",") + c;
    std::ifstream csv(files_->part(".csv"), std::ios::binary);
    std::string first;
    if (!std::getline(csv, first) || first != header)
      throw std::runtime_error("the checkpoint's history has other columns than this deck's");
  });
  blockRuns_ = BlockRuns();
}

void OutputManager::finish() {
  onRoot([&] {
    writer_.reset();  // closes the Exodus file before it is renamed
    history_.reset();
    files_->commit();
  });
}

void OutputManager::abandon(const std::string& verb, const std::string& line) noexcept {
  if (!files_) return;  // not rank 0, or the files were never opened
  writer_.reset();
  history_.reset();
  std::string when = "before the first step";
  if (lastStep_ >= 0) {
    std::ostringstream t;
    t << "after step " << lastStep_ << " (t = " << lastTime_ << ")";
    when = t.str();
  }
  files_->abandon(verb + " " + when + ": " + line);
}

}  // namespace pf
