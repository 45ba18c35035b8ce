#include "OutputManager.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ExodusWriter.hpp"
#include "core/OutputFields.hpp"
#include "HistoryWriter.hpp"
#include "core/InputError.hpp"
#include "input/InputSchema.hpp"

namespace pf {
namespace {

// The core's fields (core/OutputFields.hpp); everything else must be a material output field.
const std::vector<std::string>& kVectors = coreVectorFields();
const std::vector<std::string>& kCoreScalars = coreScalarFields();
const std::vector<std::string>& kGlobals = globalFields();  // written as Exodus global variables

// Peridigm requests "Element_Id" but writes the variable as "ID"; exodiff against its gold files needs the same.
std::string exodusName(const std::string& var) { return var == "Element_Id" ? "ID" : var; }

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

OutputManager::OutputManager(const Teuchos::ParameterList& input, const std::string& listName,
                             const std::string& inputFile, Problem& problem)
    : pb_(problem), model_(*problem.model) {
  const bool root = model_.layout().rank() == 0;
  const StateStore& state = model_.state();
  // Peridigm's Verlet integrator defines the acceleration (f + b)/rho it steps with; the quasi-static
  // solvers have none, so asking for it there is an error rather than a field of zeros. With several
  // solver lists (Solver1, Solver2, ...) one Verlet among them is enough.
  bool dynamic = false;
  for (auto it = input.begin(); it != input.end(); ++it) {
    const std::string& n = input.name(it);
    if (input.entry(it).isList() && n.compare(0, 6, "Solver") == 0 && input.sublist(n).isSublist("Verlet"))
      dynamic = true;
  }
  auto checkVariable = [&](const std::string& var, const std::string& where) {
    if (var == "Acceleration" && !dynamic)
      throw InputError(inputFile + ": " + where + ": 'Acceleration' is only written by the Verlet solver");
    if (contains(kVectors, var) || contains(kCoreScalars, var)) return;
    if (state.has(var) && state.spec(var).output && state.spec(var).where == Location::Node) {
      for (const BlockModel& b : model_.blocks()) b.material->enableOutput(var);
      return;
    }
    throw InputError(inputFile + ": " + where + ": '" + var + "' is not computed by any material of this run");
  };

  if (input.isSublist(listName)) {
    const std::string& L = listName;
    const Teuchos::ParameterList& out = input.sublist(listName);
    const std::string stem = getText(out, "Output Filename", "periforge");
    exodus_ = getText(out, "Output File Type", "ExodusII") == "ExodusII";
    exodusName_ = stem + ".e";
    historyName_ = stem + ".csv";
    frequency_ = getInteger(out, "Output Frequency", 1);
    if (frequency_ < 1) throw InputError(inputFile + ": " + L + ": 'Output Frequency' must be at least 1");
    first_ = getInteger(out, "Initial Output Step", 1);
    last_ = getInteger(out, "Final Output Step", 0);
    if (out.isSublist("Output Variables")) {
      const Teuchos::ParameterList& vars = out.sublist("Output Variables");
      for (auto it = vars.begin(); it != vars.end(); ++it) {
        const std::string var = vars.name(it);
        if (!getFlag(vars, var, false)) continue;
        if (contains(kGlobals, var)) {
          globals_.push_back(var);
          continue;
        }
        checkVariable(var, L + "/Output Variables");
        (contains(kVectors, var) ? nodalVectors_ : elementScalars_).push_back(var);
      }
    }
    if (out.isSublist("Probes")) {
      const Teuchos::ParameterList& pl = out.sublist("Probes");
      for (auto it = pl.begin(); it != pl.end(); ++it) {
        const std::string name = pl.name(it);
        const Teuchos::ParameterList& p = pl.sublist(name);
        const double at[3] = {getNumber(p, "X"), getNumber(p, "Y"), getNumber(p, "Z", 0.0)};
        // Nearest point of the whole cloud, ties to the lowest id, so every rank picks the same one.
        int best = -1;
        double bestD = std::numeric_limits<double>::max();
        for (int q = 0; q < pb_.cloud.size(); ++q) {
          double d = 0;
          for (int c = 0; c < 3; ++c) d += (pb_.cloud.x[3 * q + c] - at[c]) * (pb_.cloud.x[3 * q + c] - at[c]);
          if (d < bestD) { bestD = d; best = q; }
        }
        Probe probe{name, -1, splitWords(getText(p, "Variables", ""))};
        if (probe.variables.empty()) throw InputError(inputFile + ": " + L + "/Probes/" + name + ": 'Variables' is empty");
        for (const std::string& var : probe.variables) checkVariable(var, L + "/Probes/" + name);
        const std::vector<int>& gids = model_.layout().gids();
        for (int i = 0; i < model_.numOwned(); ++i)
          if (gids[i] == best) probe.local = i;
        probes_.push_back(probe);
        if (root) std::printf("probe %s: node %d at (%g, %g, %g)\n", name.c_str(), best + 1, pb_.cloud.x[3 * best],
                              pb_.cloud.x[3 * best + 1], pb_.cloud.x[3 * best + 2]);
      }
    }
    auto commaList = [&](const std::string& param) {  // comma-separated: node-set names may contain spaces
      std::vector<std::string> items;
      std::string item;
      for (std::istringstream in(getText(out, param, "")); std::getline(in, item, ',');) {
        item.erase(0, item.find_first_not_of(" \t\n"));
        item.erase(item.find_last_not_of(" \t\n") + 1);
        if (!item.empty()) items.push_back(item);
      }
      return items;
    };
    std::vector<std::string> sets = pb_.prescribedNodeSets;
    if (out.isParameter("Reactions")) sets = commaList("Reactions");
    std::vector<std::string> labels = sets;
    if (out.isParameter("Reaction Names")) labels = commaList("Reaction Names");
    if (labels.size() != sets.size())
      throw InputError(inputFile + ": " + L + ": 'Reaction Names' needs one name per entry of 'Reactions'");
    for (std::size_t k = 0; k < sets.size(); ++k) {
      const std::string& s = sets[k];
      auto it = pb_.nodeSets.find(s);
      if (it == pb_.nodeSets.end()) throw InputError(inputFile + ": " + L + ": 'Reactions' names unknown node set '" + s + "'");
      Reaction r{s, labels[k], {}};
      const std::vector<int>& gids = model_.layout().gids();
      std::vector<char> in(pb_.cloud.size(), 0);
      for (int q : it->second) in[q] = 1;
      for (int i = 0; i < model_.numOwned(); ++i)
        if (in[gids[i]]) r.nodes.push_back(i);
      reactions_.push_back(r);
    }
    if (out.isParameter("Applied Displacement")) {
      const std::string bc = getText(out, "Applied Displacement", "");
      const Teuchos::ParameterList* bcs =
          input.isSublist("Boundary Conditions") ? &input.sublist("Boundary Conditions") : nullptr;
      if (!bcs || !bcs->isSublist(bc) || getText(bcs->sublist(bc), "Type", "") != "Prescribed Displacement")
        throw InputError(inputFile + ": " + L + ": 'Applied Displacement' = '" + bc +
                         "' is not a Prescribed Displacement condition");
      applied_ = std::make_shared<Expression>(scalarAsText(bcs->sublist(bc).getEntry("Value")),
                                              inputFile + ": Boundary Conditions/" + bc + "/Value");
      if (applied_->dependsOnSpace())
        throw InputError(inputFile + ": " + L + ": 'Applied Displacement' = '" + bc + "': its Value depends on x, y or z");
    }
  }
  if (historyName_.empty()) return;  // no Output list: nothing is written

  if (root) {
    std::vector<std::string> cols = {"time", "step"};
    if (applied_) cols.push_back("Applied_Displacement");
    auto label = [](std::string s) {
      std::replace(s.begin(), s.end(), ' ', '_');
      return s;
    };
    for (const Reaction& r : reactions_)
      for (const char* c : {"X", "Y", "Z"}) cols.push_back("Reaction_" + label(r.label) + "_" + c);
    for (const Probe& p : probes_)
      for (const std::string& var : p.variables) {
        if (contains(kVectors, var))
          for (const char* c : {"X", "Y", "Z"}) cols.push_back("Probe_" + label(p.name) + "_" + var + c);
        else
          cols.push_back("Probe_" + label(p.name) + "_" + var);
      }
    history_ = std::make_unique<HistoryWriter>(historyName_, cols);
    if (exodus_) {
      std::vector<std::string> scalars, elements;
      for (const std::string& var : elementScalars_) elements.push_back(exodusName(var));
      if (nodalVectors_.empty() && elements.empty() && !globals_.empty())
        // Peridigm's file for global data only: one dummy node at the origin in one one-element block.
        writer_ = std::make_unique<ExodusWriter>(exodusName_, std::vector<double>{0.0, 0.0, 0.0}, std::vector<int>{1},
                                                 false, nodalVectors_, scalars, elements, globals_);
      else
        writer_ = std::make_unique<ExodusWriter>(exodusName_, pb_.cloud.x, pb_.cloud.block, pb_.cloud.planar,
                                                 nodalVectors_, scalars, elements, globals_);
    }
  }
  bodyForce_.assign(model_.numDofs(), 0.0);
}

OutputManager::~OutputManager() = default;

double OutputManager::nodeValue(const std::string& var, int comp, int i, const std::vector<double>& u,
                                const std::vector<double>& v, const std::vector<double>& f) const {
  const std::vector<double>& x = model_.coordinates();
  if (var == "Displacement") return u[3 * i + comp];
  if (var == "Velocity") return v[3 * i + comp];
  if (var == "Force_Density") return f[3 * i + comp];
  if (var == "Force") return f[3 * i + comp] * model_.volume()[i];
  // bodyForce_ holds b at the step's time (onStep fills it first) or zeros.
  if (var == "Acceleration") return (f[3 * i + comp] + bodyForce_[3 * i + comp]) / model_.density()[i];
  if (var == "Model_Coordinates") return x[3 * i + comp];
  if (var == "Coordinates") return x[3 * i + comp] + u[3 * i + comp];
  if (var == "Weighted_Volume") return model_.weightedVolume()[i];
  if (var == "Element_Id") return model_.layout().gids()[i] + 1;
  if (var == "Proc_Num") return model_.layout().rank();
  if (var == "Number_Of_Neighbors") return model_.numNeighbors(i);
  if (var == "Volume") return model_.volume()[i];
  if (var == "Horizon")  // the horizon of the node's block
    for (const BlockModel& b : model_.blocks())
      if (i >= b.begin && i < b.end) return b.horizon;
  return model_.state().committed(var)[i];
}

std::vector<double> OutputManager::ownedField(const std::string& var, int ncomp, const std::vector<double>& u,
                                              const std::vector<double>& v, const std::vector<double>& f) const {
  std::vector<double> out(static_cast<std::size_t>(ncomp) * model_.numOwned());
  for (int i = 0; i < model_.numOwned(); ++i)
    for (int c = 0; c < ncomp; ++c) out[ncomp * i + c] = nodeValue(var, c, i, u, v, f);
  return out;
}

void OutputManager::onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
                           const std::vector<double>& f) {
  if (historyName_.empty()) return;
  ++count_;
  if (count_ < first_ || (last_ > 0 && count_ > last_ + 1) || (count_ - 1) % frequency_ != 0) return;
  const bool root = model_.layout().rank() == 0;
  const Communicator& comm = model_.layout().comm();

  // History row: reactions and probes are reduced over ranks (a probe lives on one rank, others add 0).
  std::vector<double> local;
  if (model_.hasBodyForce()) model_.bodyForce(report.time, bodyForce_.data());
  for (const Reaction& r : reactions_)
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int i : r.nodes) s -= (f[3 * i + c] + bodyForce_[3 * i + c]) * model_.volume()[i];
      local.push_back(s);
    }
  for (const Probe& p : probes_)
    for (const std::string& var : p.variables) {
      const int ncomp = contains(kVectors, var) ? 3 : 1;
      for (int c = 0; c < ncomp; ++c) local.push_back(p.local >= 0 ? nodeValue(var, c, p.local, u, v, f) : 0.0);
    }
  std::vector<double> global(local.size());
  if (!local.empty()) comm.sum(local.data(), global.data(), static_cast<int>(local.size()));
  if (root) {
    std::vector<double> row = {report.time, static_cast<double>(count_ - 1)};
    if (applied_) row.push_back((*applied_)(0.0, 0.0, 0.0, report.time));
    row.insert(row.end(), global.begin(), global.end());
    history_->writeRow(row);
  }

  if (!exodus_) return;
  std::map<std::string, double> globals;
  for (const std::string& var : globals_) {
    double ke = 0.0;  // Global_Kinetic_Energy = sum 1/2 rho V |v|^2
    for (int i = 0; i < model_.numOwned(); ++i)
      ke += 0.5 * model_.density()[i] * model_.volume()[i] *
            (v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
    globals[var] = model_.sum(ke);
  }
  std::map<std::string, std::vector<double>> vectors, scalars, none;
  for (const std::string& var : nodalVectors_) {
    std::vector<double> owned = ownedField(var, 3, u, v, f);
    vectors[var] = model_.layout().gatherToRoot(owned.data(), 3);
  }
  for (const std::string& var : elementScalars_) {
    std::vector<double> owned = ownedField(var, 1, u, v, f);
    scalars[exodusName(var)] = model_.layout().gatherToRoot(owned.data(), 1);
  }
  if (root) writer_->writeStep(report.time, vectors, none, scalars, globals);
}

}  // namespace pf
