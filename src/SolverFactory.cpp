#include "SolverFactory.hpp"

#include "AdrSolver.hpp"
#include "InputError.hpp"
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

std::unique_ptr<Solver> makeSolver(const Teuchos::ParameterList& s, const std::string& inputFile) {
  const std::string where = inputFile + ": Solver";
  if (s.isSublist("Verlet")) {
    const Teuchos::ParameterList& l = s.sublist("Verlet");
    VerletOptions o;
    o.fixedDt = get<double>(l, "Fixed dt", 0.0);
    o.safetyFactor = get<double>(l, "Safety Factor", o.safetyFactor);
    if (l.isParameter("Fixed dt")) requirePositive(o.fixedDt, where + "/Verlet", "Fixed dt");
    requirePositive(o.safetyFactor, where + "/Verlet", "Safety Factor");
    return std::make_unique<VerletSolver>(o);
  }
  AdrOptions o;
  const bool peridigmQs = s.isSublist("QuasiStatic");
  const Teuchos::ParameterList& l = peridigmQs ? s.sublist("QuasiStatic") : s.sublist("Adaptive Dynamic Relaxation");
  const std::string lw = where + (peridigmQs ? "/QuasiStatic" : "/Adaptive Dynamic Relaxation");
  o.loadSteps = get<int>(l, "Number of Load Steps", 1);
  if (o.loadSteps < 1) throw InputError(lw + ": 'Number of Load Steps' must be at least 1");
  o.relativeTolerance = get<double>(l, "Relative Tolerance", o.relativeTolerance);
  o.absoluteTolerance = get<double>(l, "Absolute Tolerance", 0.0);
  if (peridigmQs) {
    // Peridigm's Newton iteration cap does not transfer to relaxation; only the tolerances do. An absolute
    // tolerance alone would stop relaxation far earlier than Newton stops, so the relative one stays on.
    o.relativeTolerance = get<double>(l, "Relative Tolerance", 1e-12);
  } else {
    o.maxIterations = get<int>(l, "Maximum Iterations", o.maxIterations);
    o.safetyFactor = get<double>(l, "Safety Factor", o.safetyFactor);
    o.verbose = get<bool>(l, "Verbose", false);
  }
  requirePositive(o.safetyFactor, lw, "Safety Factor");
  if (o.relativeTolerance < 0 || o.absoluteTolerance < 0) throw InputError(lw + ": tolerances must not be negative");
  if (o.maxIterations < 1) throw InputError(lw + ": 'Maximum Iterations' must be at least 1");
  return std::make_unique<AdrSolver>(o);
}

}  // namespace pf
