// The top level of a deck: which lists it may hold, then each section in dependency order (blocks give
// the default layer width, node sets the names conditions and reactions refer to).
#include "DeckParser.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "Input.hpp"
#include "Sections.hpp"
#include "core/Log.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

namespace {

// The output lists: Output, then Peridigm's numbered Output1, Output2, ..., then, as Peridigm reads them, every
// other top-level list whose name contains "Output" ("Output Data", "Output History 1") in deck order.
std::vector<std::string> outputLists(const PL& p) {
  std::vector<std::string> lists = numberedLists(p, "Output");
  for (auto it = p.begin(); it != p.end(); ++it) {
    const std::string& n = p.name(it);
    if (p.entry(it).isList() && n.find("Output") != std::string::npos &&
        std::find(lists.begin(), lists.end(), n) == lists.end() &&
        !(n.compare(0, 6, "Output") == 0 && n.size() > 6 && n.find_first_not_of("0123456789", 6) == std::string::npos))
      lists.push_back(n);
  }
  return lists;
}

// Top-level sub-lists a deck may hold; Peridigm's numbered Solver<n>/Output<n> lists with n = 1, 2, ...
std::vector<std::string> topLists(const PL& p, const std::string& file) {
  std::vector<std::string> tops = {"Discretization", "Materials", "Blocks", "Boundary Conditions", "Restart",
                                    "Damage Models", "Compute Class Parameters", "Contact", "Data Loader"};
  for (const std::string stem : {"Solver", "Output"}) {
    const std::vector<std::string> lists = stem == "Output" ? outputLists(p) : numberedLists(p, stem);
    tops.insert(tops.end(), lists.begin(), lists.end());
    if (!p.isSublist(stem)) tops.push_back(stem);  // so that a missing one is reported as such
  }
  for (const std::string& n : outputLists(p))
    if (std::find(tops.begin(), tops.end(), n) == tops.end()) tops.push_back(n);
  for (auto it = p.begin(); it != p.end(); ++it) {
    const std::string& n = p.name(it);
    for (const std::string stem : {"Solver", "Output"})
      if (p.entry(it).isList() && n.size() > stem.size() && n.compare(0, stem.size(), stem) == 0 &&
          n.find_first_not_of("0123456789", stem.size()) == std::string::npos &&
          (n[stem.size()] == '0' || std::find(tops.begin(), tops.end(), n) == tops.end()))
        fail(file, "top level", "'" + n + "': a numbered " + stem + " list is " + stem +
                                    "<n> with n = 1, 2, ... (no leading zero)");
  }
  return tops;
}

std::vector<SolverSpec> solvers(const PL& p, const std::string& file) {
  const std::vector<std::string> lists = numberedLists(p, "Solver");
  if (p.isSublist("Solver") && lists.size() > 1)
    fail(file, "top level", "give either one 'Solver' list or numbered ones ('" + lists[1] + "', ...), not both");
  if (lists.empty()) fail(file, "top level", "missing required sub-list 'Solver' (or 'Solver1', ...)");
  std::vector<SolverSpec> out;
  for (const std::string& n : lists) out.push_back(parseSolver(p.sublist(n), file, n));
  return out;
}

std::vector<OutputSpec> outputs(const PL& p, const Deck& deck, const std::set<std::string>& nodeSets) {
  std::vector<OutputSpec> out;
  std::set<std::string> labels;
  for (const ComputeSpec& c : deck.computes) labels.insert(c.label);
  if (deck.dataLoader.given) labels.insert(deck.dataLoader.field);
  std::map<std::string, std::size_t> files;  // Output Filename -> its list in out
  for (const std::string& n : outputLists(p)) {
    OutputSpec o = parseOutput(p.sublist(n), deck.file, n, nodeSets, deck.conditions, deck.hasDynamicSolver(), labels);
    const auto it = files.find(o.filename);
    if (it == files.end()) {
      files[o.filename] = out.size();
      out.push_back(std::move(o));
      continue;
    }
    // Peridigm's suite decks give a second list of the same file (the first's globals again, or other globals at
    // another frequency); Peridigm's gold file is then the first list's alone (ElasticBondBased*,
    // ElasticPlasticCorrespondenceFullyPrescribedTension, ...). So the later list is dropped, with a warning.
    warn(deck.file + ": " + n + ": 'Output Filename' = '" + o.filename + "' is also the file of '" +
         out[it->second].listName + "': the file is '" + out[it->second].listName + "''s alone (as Peridigm's); '" +
         n + "' writes nothing");
  }
  return out;
}

// A 2D material's Thickness (Height) enters its constants, the discretization's the points' volumes: two different
// values would give a model that is neither (the forces follow the volumes). A Text File mesh holds its
// thickness in its volumes only, and is not checked.
void requireOneThickness(const Deck& deck) {
  const double h = deck.discretization.thickness;
  if (!(h > 0.0)) return;
  for (const BlockGroupSpec& b : deck.blocks) {
    const MaterialSpec& m = deck.material(b.material);
    const std::string name = m.values.has("Height") ? "Height" : "Thickness";  // Elastic Bond Based's: Height
    if (!m.values.has(name)) continue;
    const double hm = m.values.get(name);
    if (std::fabs(hm - h) > 1e-12 * h)
      fail(deck.file, "Materials/" + m.name, "'" + name + "' = " + numberText(hm) + " differs from the Discretization's " +
                                                 numberText(h) + " (the points' volumes): give both the same value");
  }
}

}  // namespace

Deck parseDeck(const PL& p, const std::string& file, const std::string& directory) {
  Deck deck;
  deck.file = file;
  deck.directory = directory;
  const ParameterSpec maxMemory = ParameterSpec::real(
      "Maximum Memory", "bytes the whole run may use (all ranks); default: the machine's MemAvailable").positive();
  // Peridigm's switch for its first Eulerian hypoelastic correspondence (2021); its current code reads it nowhere
  // (the model allocates its own fields), so its decks' value changes nothing here either.
  const ParameterSpec hypoelastic = ParameterSpec::flag(
      "Enable Bond-Associated Hypoelastic Model", "accepted and ignored, as by Peridigm since 2021");
  const ParameterValues top =
      readList(p, {ParameterSpec::flag("Verbose"), maxMemory, hypoelastic}, topLists(p, file), file, "top level");
  deck.verbose = top.get("Verbose", 0.0) != 0.0;
  deck.maxMemory = top.get("Maximum Memory", 0.0);
  deck.solvers = solvers(p, file);
  deck.discretization = parseDiscretization(requireSublist(p, "Discretization", file, "top level"), file, directory);
  deck.materials = parseMaterials(p, file);
  deck.damageModels = parseDamageModels(p, file, directory);
  deck.blocks = parseBlocks(p, deck.materials, deck.damageModels, file, deck.discretization.meshBlockNames);
  requireOneThickness(deck);
  applyDefaultLayerWidth(deck.discretization, deck.maxHorizon(), file);
  const std::vector<std::string> generated = generatedNodeSetNames(deck.discretization);
  std::set<std::string> nodeSets(generated.begin(), generated.end());
  nodeSets.insert("All");
  if (p.isSublist("Boundary Conditions")) {
    const PL& bcs = p.sublist("Boundary Conditions");
    deck.nodeSets = parseNodeSets(bcs, nodeSets, file, directory);
    for (const NodeSetSpec& s : deck.nodeSets) nodeSets.insert(s.name);
    deck.conditions = parseConditions(bcs, nodeSets, file);
    deck.walls = parseRigidWalls(bcs, nodeSets, deck.solvers, file);
  }
  deck.contact = parseContact(p, deck.solvers, deck.blocks, file);
  if (p.isSublist("Compute Class Parameters"))
    deck.computes = parseComputes(p.sublist("Compute Class Parameters"), nodeSets, file);
  if (p.isSublist("Data Loader"))
    deck.dataLoader = parseDataLoader(p.sublist("Data Loader"), file, directory, deck.solvers);
  deck.outputs = outputs(p, deck, nodeSets);
  if (p.isSublist("Restart")) deck.restart = parseRestart(p.sublist("Restart"), file, deck.outputs);
  if (deck.restart.given && deck.discretization.constructInterfaces)  // the checkpoint does not carry its file
    fail(file, "Restart", "a restart cannot continue 'Discretization/Construct Interfaces''s file: give one or the other");
  checkWrittenFiles(deck);
  return deck;
}

Deck readDeck(const std::string& path) {
  return parseDeck(*readInput(path), path, inputDirectory(path));
}

const MaterialSpec& Deck::material(const std::string& name) const {
  for (const MaterialSpec& m : materials)
    if (m.name == name) return m;
  throw std::logic_error("no material '" + name + "' in the deck");  // parseBlocks checked every name
}

const DamageModelSpec* Deck::damageModel(const std::string& name) const {
  for (const DamageModelSpec& d : damageModels)
    if (d.name == name) return &d;
  return nullptr;  // "" (parseBlocks checked every other name)
}

double Deck::maxHorizon() const {
  double h = 0.0;
  for (const BlockGroupSpec& b : blocks) h = std::max(h, b.horizon);
  return h;
}

bool Deck::hasDynamicSolver() const {
  for (const SolverSpec& s : solvers)
    if (findSolver(s.type)->dynamic) return true;
  return false;
}

}  // namespace pf
