#include "SolverFactory.hpp"

#include <algorithm>
#include <sstream>

#include "AdrSolver.hpp"
#include "core/InputError.hpp"
#include "input/InputSchema.hpp"
#include "NoxQuasiStaticSolver.hpp"
#include "VerletSolver.hpp"

namespace pf {
namespace {

template <class T>
T get(const Teuchos::ParameterList& l, const std::string& name, T fallback) {
  return l.isParameter(name) ? l.get<T>(name) : fallback;
}

void requirePositive(double v, const std::string& where, const std::string& name) {
  if (!(v > 0)) throw InputError(where + ": '" + name + "' must be positive");
}

}  // namespace

std::vector<double> solverTimes(const Teuchos::ParameterList& s) {
  const double t0 = s.isParameter("Initial Time") ? getNumber(s, "Initial Time") : 0.0;
  const Teuchos::ParameterList* steps = nullptr;
  for (const char* n : {"QuasiStatic", "NOXQuasiStatic", "Adaptive Dynamic Relaxation"})
    if (s.isSublist(n)) steps = &s.sublist(n);
  // Peridigm's explicit list of load times (validateInput allows it without Number of Load Steps only).
  if (steps && steps->isParameter("Time Steps")) {
    std::vector<double> times;
    std::istringstream in(steps->get<std::string>("Time Steps"));
    for (double t; in >> t;) times.push_back(t);
    return times;
  }
  const double t1 = getNumber(s, "Final Time");
  if (!steps) return {t0, t1};
  const int n = getInteger(*steps, "Number of Load Steps", 1);
  std::vector<double> times = {t0};
  for (int k = 1; k <= n; ++k) times.push_back(t0 + (t1 - t0) * k / n);  // Peridigm's t0 + k (t1 - t0) / n
  return times;
}

std::unique_ptr<Solver> makeSolver(const Teuchos::ParameterList& s, const std::string& inputFile,
                                   const std::string& listName) {
  const std::string where = inputFile + ": " + listName;
  if (s.isSublist("Verlet")) {
    const Teuchos::ParameterList& l = s.sublist("Verlet");
    VerletOptions o;
    o.fixedDt = get<double>(l, "Fixed dt", 0.0);
    o.safetyFactor = get<double>(l, "Safety Factor", o.safetyFactor);
    if (l.isParameter("Fixed dt")) requirePositive(o.fixedDt, where + "/Verlet", "Fixed dt");
    requirePositive(o.safetyFactor, where + "/Verlet", "Safety Factor");
    return std::make_unique<VerletSolver>(o);
  }
  if (s.isSublist("QuasiStatic") || s.isSublist("NOXQuasiStatic")) {
    // Peridigm's QuasiStatic (Newton) and NOXQuasiStatic lists are both served by the NOX engine.
    const bool peridigmQs = s.isSublist("QuasiStatic");
    const Teuchos::ParameterList& l = s.sublist(peridigmQs ? "QuasiStatic" : "NOXQuasiStatic");
    const std::string lw = where + (peridigmQs ? "/QuasiStatic" : "/NOXQuasiStatic");
    NoxOptions o;
    // Peridigm's decks give one of the two; an absolute tolerance alone means just that test.
    const bool absOnly = l.isParameter("Absolute Tolerance") && !l.isParameter("Relative Tolerance");
    o.relativeTolerance = absOnly ? 0.0 : get<double>(l, "Relative Tolerance", o.relativeTolerance);
    o.absoluteTolerance = get<double>(l, "Absolute Tolerance", 0.0);
    o.maxIterations = get<int>(l, "Maximum Solver Iterations", get<int>(l, "Max Solver Iterations", o.maxIterations));
    o.maxCuts = get<int>(l, "Maximum Load Step Cuts", o.maxCuts);
    o.verbose = get<bool>(l, "Verbose", false);
    o.precBondRadius = get<double>(l, "Preconditioner Bond Radius", o.precBondRadius);
    if (!(o.precBondRadius >= 1)) throw InputError(lw + ": 'Preconditioner Bond Radius' must be at least 1");
    if (o.relativeTolerance < 0 || o.absoluteTolerance < 0) throw InputError(lw + ": tolerances must not be negative");
    if (o.maxIterations < 1) throw InputError(lw + ": 'Maximum Solver Iterations' must be at least 1");
    if (o.maxCuts < 0) throw InputError(lw + ": 'Maximum Load Step Cuts' must not be negative");
    for (const char* nox : {"Direction", "Line Search", "Printing", "Solver Options"})
      if (l.isSublist(nox)) o.nox.set(nox, l.sublist(nox));
    if (l.isParameter("Nonlinear Solver")) o.nox.set("Nonlinear Solver", l.get<std::string>("Nonlinear Solver"));
    o.fallback.relativeTolerance = std::max(o.relativeTolerance, 1e-10);  // ADR's round-off floor is ~3e-13
    o.fallback.absoluteTolerance = o.absoluteTolerance;
    return std::make_unique<NoxQuasiStaticSolver>(o);
  }
  AdrOptions o;
  const Teuchos::ParameterList& l = s.sublist("Adaptive Dynamic Relaxation");
  const std::string lw = where + "/Adaptive Dynamic Relaxation";
  o.relativeTolerance = get<double>(l, "Relative Tolerance", o.relativeTolerance);
  o.absoluteTolerance = get<double>(l, "Absolute Tolerance", 0.0);
  o.maxIterations = get<int>(l, "Maximum Iterations", o.maxIterations);
  o.safetyFactor = get<double>(l, "Safety Factor", o.safetyFactor);
  o.verbose = get<bool>(l, "Verbose", false);
  requirePositive(o.safetyFactor, lw, "Safety Factor");
  if (o.relativeTolerance < 0 || o.absoluteTolerance < 0) throw InputError(lw + ": tolerances must not be negative");
  if (o.maxIterations < 1) throw InputError(lw + ": 'Maximum Iterations' must be at least 1");
  return std::make_unique<AdrSolver>(o);
}

}  // namespace pf
