// An "Output" list (or Peridigm's Output1, Output2, ..., "Output Data": any name containing Output) -> OutputSpec.
#include <set>

#include "Sections.hpp"
#include "core/OutputFields.hpp"

namespace pf {

// The core's fields and every registered model's declared outputs (the registries are fixed: built once).
const std::vector<std::string>& knownOutputVariables() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = coreVectorFields();
    for (const auto* list : {&coreScalarFields(), &fieldScalarOutputs(), &globalFields(), &tensorFields(),
                              &materialVectorFields()}) n.insert(n.end(), list->begin(), list->end());
    for (const MaterialEntry& e : materialRegistry())
      for (const std::string& o : e.outputs)
        if (std::find(n.begin(), n.end(), o) == n.end()) n.push_back(o);
    return n;
  }();
  return names;
}

namespace {

using S = ParameterSpec;

void checkVariable(const std::string& var, bool dynamic, const std::string& file, const std::string& path,
                   const std::string& param) {
  const std::vector<std::string>& known = knownOutputVariables();
  if (std::find(known.begin(), known.end(), var) == known.end())
    fail(file, path, "'" + param + "' names unknown output variable '" + var + "'");
  // Peridigm's dynamic integrators (Verlet, Implicit) define the acceleration (f + b)/rho they step with;
  // the quasi-static solvers have none, so asking for it there is an error rather than a field of zeros.
  if (var == "Acceleration" && !dynamic)
    fail(file, path, "'Acceleration' is only written by a dynamic solver (Verlet, Implicit)");
}

std::vector<std::string> outputVariables(const PL& v, bool dynamic, const std::string& file, const std::string& path,
                                         const std::set<std::string>& computeLabels) {
  // Peridigm fields its regression decks request that Periforge does not compute: named as such rather
  // than as unknown, so the deck's author knows the request was understood.
  for (const char* n : {"Strain_Energy", "Neighborhood_Volume"})
    if (v.isParameter(n)) fail(file, path, std::string("Peridigm's output variable '") + n + "' is not supported by Periforge");
  std::vector<ParameterSpec> specs;
  for (const std::string& n : knownOutputVariables()) specs.push_back(S::flag(n));
  for (const std::string& n : computeLabels) specs.push_back(S::flag(n));
  const ParameterValues values = readList(v, specs, {}, file, path);
  std::vector<std::string> out;
  for (auto it = v.begin(); it != v.end(); ++it)
    if (values.flag(v.name(it))) {
      if (!computeLabels.count(v.name(it))) checkVariable(v.name(it), dynamic, file, path, "Output Variables");
      out.push_back(v.name(it));
    }
  return out;
}

std::vector<ProbeSpec> probes(const PL& probes, bool dynamic, const std::string& file, const std::string& path) {
  std::vector<ProbeSpec> out;
  for (auto it = probes.begin(); it != probes.end(); ++it) {
    const std::string ppath = path + "/" + probes.name(it);
    if (!probes.entry(it).isList())
      fail(file, path, "unknown parameter '" + probes.name(it) + "' (each probe is a sub-list)");
    const ParameterValues p = readList(probes.sublist(probes.name(it)), probeSpecs(), {}, file, ppath);
    ProbeSpec s;
    s.name = probes.name(it);
    s.at = {p.get("X"), p.get("Y"), p.get("Z")};
    s.variables = splitWords(p.text("Variables"));
    if (s.variables.empty()) fail(file, ppath, "'Variables' is empty");
    for (const std::string& var : s.variables) {
      checkVariable(var, dynamic, file, ppath, "Variables");
      if (isTensorField(var) || isMaterialVectorField(var))  // a history column is one number
        fail(file, ppath, "'Variables' names '" + var + "', a tensor or vector: a probe takes one component ('" +
                              var + (isTensorField(var) ? "XX" : "X") + "', ...)");
    }
    out.push_back(s);
  }
  return out;
}

// "Applied Displacement": a Prescribed Displacement whose value is one number per time.
std::shared_ptr<const Expression> appliedDisplacement(const std::string& bc, const std::vector<ConditionSpec>& conditions,
                                                      const std::string& file, const std::string& path) {
  const ConditionSpec* c = nullptr;
  for (const ConditionSpec& x : conditions)
    if (x.name == bc) c = &x;
  if (!c) fail(file, path, "'Applied Displacement' = '" + bc + "' is not a condition of Boundary Conditions");
  if (c->kind != ConditionSpec::Kind::PrescribedDisplacement)
    fail(file, path, "'Applied Displacement' = '" + bc + "' is not a Prescribed Displacement");
  if (c->value->dependsOnSpace())
    fail(file, path, "'Applied Displacement' = '" + bc + "': its Value depends on x, y or z (one value per time is needed)");
  return c->value;
}

void reactions(const ParameterValues& o, const std::set<std::string>& nodeSets, OutputSpec& s, const std::string& file,
               const std::string& path) {
  if (o.has("Reaction Names") && !o.has("Reactions"))
    fail(file, path, "'Reaction Names' needs 'Reactions' (one name per entry)");
  if (!o.has("Reactions")) return;
  s.reactionsGiven = true;
  s.reactions = commaList(o.text("Reactions"), "Reactions", file, path);
  for (const std::string& r : s.reactions)
    if (!nodeSets.count(r)) fail(file, path, "'Reactions' names undefined node set '" + r + "'");
  s.reactionNames = s.reactions;
  if (!o.has("Reaction Names")) return;
  s.reactionNames = commaList(o.text("Reaction Names"), "Reaction Names", file, path);
  if (s.reactionNames.size() != s.reactions.size())
    fail(file, path, "'Reaction Names' has " + std::to_string(s.reactionNames.size()) + " entries, 'Reactions' has " +
                         std::to_string(s.reactions.size()));
  std::set<std::string> seen;
  for (const std::string& n : s.reactionNames)
    if (!seen.insert(n).second) fail(file, path, "'Reaction Names' repeats '" + n + "'");
}

}  // namespace

std::vector<ParameterSpec> outputSpecs() {
  return {
      S::text("Output Filename", "base name of the Exodus (`.e`) and history (`.csv`) files").need(),
      S::text("Output File Type", "only `ExodusII`").byDefault("ExodusII").oneOf({"ExodusII"}),
      S::text("Output Format", "only `BINARY` (Peridigm's; accepted)").oneOf({"BINARY"}),
      S::integer("Output Frequency", "write every n-th step (see below)").byDefault("1").atLeast(1),
      S::integer("Initial Output Step", "Peridigm's: first reported step n that may be written").byDefault("1").atLeast(1),
      S::integer("Final Output Step", "Peridigm's: steps n up to `Final Output Step` + 1 may be written (default: no limit)")
          .atLeast(1),
      S::flag("Parallel Write", "Peridigm's; accepted"),
      S::text("Reactions", "node sets whose reaction force is recorded, **comma-separated** (names may contain "
                           "spaces); default: every node set of a Prescribed Displacement"),
      S::text("Reaction Names", "needs `Reactions`: one short name per entry, comma-separated, distinct; the columns "
                                "become `Reaction_<name>_X/Y/Z`"),
      S::text("Applied Displacement", "a `Prescribed Displacement` condition whose `Value` does not depend on x, y, z; "
                                      "adds the column `Applied_Displacement` after `step`")};
}

std::vector<ParameterSpec> probeSpecs() {
  return {S::real("X", "probe position (reference configuration)").need(), S::real("Y", "").need(),
          S::real("Z", "").byDefault("0"),
          S::text("Variables", "output variables, space- or comma-separated; the nearest point's values").need()};
}

OutputSpec parseOutput(const PL& o, const std::string& file, const std::string& path,
                       const std::set<std::string>& nodeSets, const std::vector<ConditionSpec>& conditions,
                       bool dynamic, const std::set<std::string>& computeLabels) {
  const ParameterValues v = readList(o, outputSpecs(), {"Output Variables", "Probes"}, file, path);
  OutputSpec s;
  s.listName = path;
  s.filename = v.text("Output Filename");
  // An empty name would write the hidden files ".csv" and ".e" in the working directory.
  if (s.filename.empty()) fail(file, path, "'Output Filename' is empty");
  s.exodus = v.text("Output File Type") == "ExodusII";
  s.frequency = static_cast<int>(v.get("Output Frequency"));
  s.firstStep = static_cast<long>(v.get("Initial Output Step"));
  s.lastStep = static_cast<long>(v.get("Final Output Step", 0.0));
  if (s.lastStep > 0 && s.lastStep + 1 < s.firstStep)
    fail(file, path, "'Final Output Step' + 1 is below 'Initial Output Step': nothing would be written");
  reactions(v, nodeSets, s, file, path);
  if (v.has("Applied Displacement"))
    s.appliedDisplacement = appliedDisplacement(v.text("Applied Displacement"), conditions, file, path);
  if (o.isSublist("Output Variables"))
    s.variables =
        outputVariables(o.sublist("Output Variables"), dynamic, file, path + "/Output Variables", computeLabels);
  if (o.isSublist("Probes")) s.probes = probes(o.sublist("Probes"), dynamic, file, path + "/Probes");
  return s;
}

}  // namespace pf
