// A "Solver" list (or Peridigm's Solver1, Solver2, ...) -> SolverSpec: the one solver sub-list checked
// against the solver registry's specs, and the load times it steps through.
#include <cmath>

#include "Sections.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

// The load times are held as a list (every rank, every solver reads them by index): past 10 million
// steps (80 MB of times) a deck is a typo or a dynamic problem, and 2e9 would take 16 GB before any check.
int loadSteps(const ParameterValues& options, const std::string& file, const std::string& sp) {
  constexpr double kMaxLoadSteps = 1.0e7;
  const double n = options.get("Number of Load Steps");
  if (n > kMaxLoadSteps)
    fail(file, sp, "'Number of Load Steps' = " + numberText(n) + " is more than 10000000 (the load times alone "
                   "would take " + numberText(8.0 * n) + " bytes); use fewer steps or a Verlet solver");
  return static_cast<int>(n);
}

// An explicit solver's fixed step: (t1 - t0) / dt steps, counted in a long. Past 2^31 - 1 steps the deck
// is a typo (a Final Time in the wrong unit, a dt of 1e-300), and past 2^63 the count overflows into a
// one-step run that ends as "done" at t0 + dt: refused here, where both times and the step are known.
void explicitSteps(const ParameterValues& options, double t0, double t1, const std::string& file,
                   const std::string& sp) {
  if (!options.has("Fixed dt")) return;  // the stable step is only known to the solver, once the model is built
  constexpr double kMaxSteps = 2147483647.0;
  const double dt = options.get("Fixed dt"), steps = (t1 - t0) / dt;
  if (!(steps <= kMaxSteps))
    fail(file, sp, "'Fixed dt' = " + numberText(dt) + " makes " + numberText(steps) + " steps from " +
                   numberText(t0) + " to " + numberText(t1) +
                   ", more than 2147483647; check the times and their units");
}

// Peridigm's QuasiStatic may list its load times ("Time Steps") instead of Final Time and a step count.
std::vector<double> timeList(const ParameterValues& q, const std::string& file, const std::string& qp) {
  std::vector<double> times;
  for (const std::string& w : splitWords(q.text("Time Steps"))) {
    std::size_t used = 0;
    double t = 0;
    try {
      t = std::stod(w, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != w.size() || !std::isfinite(t)) fail(file, qp, "'Time Steps' entry '" + w + "' is not a number");
    if (!times.empty() && !(t > times.back()))
      fail(file, qp, "'Time Steps' must increase (" + numberText(t) + " follows " + numberText(times.back()) + ")");
    times.push_back(t);
  }
  if (times.size() < 2) fail(file, qp, "'Time Steps' needs the initial time and at least one load time");
  return times;
}

}  // namespace

std::vector<ParameterSpec> solverListSpecs() {
  // Peridigm's two list-level options of its implicit solvers are accepted for its decks; neither changes
  // Periforge's answer (docs/input.md, "Solver"): the preconditioner is always Periforge's pair stiffness (or
  // none, by the Linear Solver's `Preconditioner`), and a solver's first step always starts from the previous
  // solver's end state (Peridigm's own gold files for `Initialize Predictor From Previous Solver` true and false
  // are identical).
  return {S::flag("Verbose", "accepted (Peridigm's)"), S::real("Initial Time", "start time").byDefault("0"),
          S::real("Final Time", "end time, > `Initial Time` (with QuasiStatic `Time Steps` and no `Number of Load Steps`: omitted or the list's last entry)"),
          S::text("Peridigm Preconditioner", "Peridigm's preconditioner matrix for NOX; accepted, Periforge's is its "
                                             "pair-stiffness matrix whatever the value")
              .oneOf({"Full Tangent", "Block 3x3", "None"}),
          S::flag("Initialize Predictor From Previous Solver",
                  "Peridigm's; accepted: each solver starts from the previous one's end state either way"),
          S::flag("Solve For Displacement", "Peridigm's: whether the solver advances the displacement; true for all "
                                            "but ImplicitDiffusion (Verlet: false for a thermal-only run)"),
          S::flag("Solve For Temperature", "Peridigm's: whether the solver advances the Temperature field: "
                                           "ImplicitDiffusion always; Verlet when true (explicit conduction and "
                                           "heating, sub-cycled); NOXQuasiStatic and QuasiStatic when true (a "
                                           "Backward Euler step after each load step; docs/thermal.md)"),
          S::flag("Solve For Pressure", "Peridigm's fluid-pressure field: not available (true is an input error)")};
}

// Peridigm's "Solve For ..." flags name the fields a solver advances: they must agree with what the solver can do.
// Returns the fields it advances: its own unless `Solve For <own>` = false, and those of mayAlsoSolve set true.
std::vector<std::string> solvedFields(const ParameterValues& list, const SolverEntry& entry, const std::string& file,
                                      const std::string& path) {
  if (list.has("Solve For Pressure") && list.flag("Solve For Pressure")) fail(file, path, "'Solve For Pressure' = true: Peridigm's fluid-pressure field is not available");
  std::vector<std::string> fields;
  for (const std::string field : {"Displacement", "Temperature"}) {
    const std::string flag = "Solve For " + field;
    const bool own = entry.solves == field;
    bool optional = false;
    for (const std::string& f : entry.mayAlsoSolve) optional = optional || f == field;
    const bool wanted = list.has(flag) ? list.flag(flag) : own;
    if (wanted && !own && !optional)
      fail(file, path, "'" + flag + "' = true but solver '" + entry.name + "' does not advance the " + field +
                           (field == "Temperature" ? " (ImplicitDiffusion, Verlet, NOXQuasiStatic and QuasiStatic do)" : ""));
    if (!wanted && own && !entry.mayOmitOwn)
      fail(file, path, "'" + flag + "' = false but solver '" + entry.name + "' advances the " + field);
    if (wanted) fields.push_back(field);
  }
  if (fields.empty())
    fail(file, path, "solver '" + entry.name + "' advances no field: set 'Solve For Displacement' or 'Solve For "
                     "Temperature' to true");
  return fields;
}

SolverSpec parseSolver(const PL& s, const std::string& file, const std::string& path) {
  std::vector<std::string> names;
  for (const SolverEntry& e : solverRegistry()) names.push_back(e.name);
  std::vector<ParameterSpec> listSpecs = solverListSpecs();
  // Peridigm (Peridigm.cpp, executeQuasiStatic): Final Time with Number of Load Steps, else the Time Steps list.
  const bool hasTimeList = s.isSublist("QuasiStatic") && s.sublist("QuasiStatic").isParameter("Time Steps") &&
                           !(s.isParameter("Final Time") && s.sublist("QuasiStatic").isParameter("Number of Load Steps"));
  if (!hasTimeList) listSpecs[2] = listSpecs[2].need();
  const ParameterValues list = readList(s, listSpecs, names, file, path);
  int count = 0;
  for (const std::string& n : names) count += s.isSublist(n) ? 1 : 0;
  if (count != 1) fail(file, path, "exactly one solver sub-list is required, one of " + joinNames(names));

  SolverSpec spec;
  spec.listName = path;
  spec.verbose = list.get("Verbose", 0.0) != 0.0;
  for (const SolverEntry& e : solverRegistry())
    if (s.isSublist(e.name)) spec.type = e.name;
  const SolverEntry& entry = *findSolver(spec.type);
  const std::string sp = path + "/" + spec.type;
  spec.fields = solvedFields(list, entry, file, path);
  const PL& sub = s.sublist(spec.type);
  spec.options = readList(sub, entry.parameters, entry.passThrough, file, sp);
  for (const std::string& n : entry.passThrough)
    if (sub.isSublist(n)) {
      ParamTree::Entry x;
      x.name = n;
      x.kind = ParamTree::Entry::Kind::List;
      x.list = std::make_shared<ParamTree>(treeOf(sub.sublist(n), file, sp + "/" + n));
      spec.passThrough.entries.push_back(x);
    }

  const double t0 = list.get("Initial Time");
  if (hasTimeList) {
    if (spec.options.has("Number of Load Steps"))
      fail(file, sp, "give 'Time Steps' or 'Number of Load Steps' (with the list's 'Final Time'), not both");
    spec.times = timeList(spec.options, file, sp);
    // Peridigm then ignores the list's Initial and Final Time; a deck may repeat the list's ends there, but a value
    // that contradicts them is a mistake of the deck, not a choice.
    if (list.has("Initial Time") && list.get("Initial Time") != spec.times.front())
      fail(file, path, "'Initial Time' (" + numberText(list.get("Initial Time")) + ") is not the first of the 'Time "
                       "Steps' (" + numberText(spec.times.front()) + "), which is the initial time");
    if (list.has("Final Time") && list.get("Final Time") != spec.times.back())
      fail(file, path, "'Final Time' (" + numberText(list.get("Final Time")) + ") is not the last of the 'Time "
                       "Steps' (" + numberText(spec.times.back()) + "), which is the final time");
    return spec;
  }
  // With the list's Final Time given, Peridigm steps by Number of Load Steps and ignores Time Steps.
  const double t1 = list.get("Final Time");
  if (!(t1 > t0)) fail(file, path, "'Final Time' (" + numberText(t1) + ") must exceed 'Initial Time' (" + numberText(t0) + ")");
  if (!entry.loadSteps) {
    explicitSteps(spec.options, t0, t1, file, sp);
    spec.times = {t0, t1};
    return spec;
  }
  if (!spec.options.has("Number of Load Steps")) fail(file, sp, "missing required parameter 'Number of Load Steps'");
  const int n = loadSteps(spec.options, file, sp);
  spec.times = {t0};
  for (int k = 1; k <= n; ++k) spec.times.push_back(t0 + (t1 - t0) * k / n);  // Peridigm's t0 + k (t1 - t0) / n
  return spec;
}

}  // namespace pf
