// The registry entries of the Newton-Krylov solver: Periforge's "NOXQuasiStatic" and Peridigm's
// "QuasiStatic", both served by NoxQuasiStaticSolver.
#include <algorithm>
#include <string>

#include "NoxQuasiStaticSolver.hpp"
#include "core/InputError.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

// peridigmQuasiStatic: Peridigm's "QuasiStatic", whose Absolute Tolerance bounds its own residual measure.
std::vector<ParameterSpec> commonSpecs(bool peridigmQuasiStatic) {
  return {S::real("Relative Tolerance", "residual / load scale (reaction + body force, never below the largest of a converged step) that ends a step; "
                                        "at least 1e-14 (about 50 machine epsilons: below, a converged step's residual is round-off "
                                        "and the step could never end)")
              .byDefault("1e-10").atLeast(1e-14),
          S::real("Absolute Tolerance",
                  std::string(peridigmQuasiStatic
                                  ? "Peridigm's QuasiStatic residual ||r||_2 + 20 ||r||_inf, r = (f + b) V the force "
                                    "[N] on the free dofs (Peridigm.cpp, computeQuasiStaticResidual), that ends a step"
                                  : "residual force-density norm [N/m^3] that ends a step") +
                      "; given alone (without `Relative Tolerance`) it is the only test")
              .positive(),
          S::integer("Maximum Solver Iterations", "Newton iterations per (sub)step").byDefault("30").atLeast(1),
          S::flag("Verbose", "print NOX's residual history").byDefault("false"),
          S::integer("Max Age Of Prec", "Peridigm's preconditioner age; accepted: Periforge builds its pair-stiffness "
                                        "preconditioner once, from the reference configuration, so nothing ages")};
}

std::unique_ptr<Solver> create(const ParameterValues& p, const ParamTree& passThrough, bool peridigmQuasiStatic) {
  NoxOptions o;
  o.newton.peridigmAbsolute = peridigmQuasiStatic;
  // Peridigm's decks give one of the two; an absolute tolerance alone means just that test.
  const bool absOnly = p.has("Absolute Tolerance") && !p.has("Relative Tolerance");
  o.newton.relativeTolerance = absOnly ? 0.0 : p.get("Relative Tolerance");
  o.newton.absoluteTolerance = p.get("Absolute Tolerance", 0.0);
  if (p.has("Maximum Solver Iterations") && p.has("Max Solver Iterations"))
    throw InputError(p.where() + ": give 'Maximum Solver Iterations' or Peridigm's spelling 'Max Solver Iterations', "
                                 "not both");
  o.newton.maxIterations = static_cast<int>(p.get("Max Solver Iterations", p.get("Maximum Solver Iterations")));
  o.maxCuts = static_cast<int>(p.get("Maximum Load Step Cuts", o.maxCuts));
  o.newton.verbose = p.flag("Verbose");
  o.newton.precBondRadius = p.get("Preconditioner Bond Radius", o.newton.precBondRadius);
  o.newton.firstSolveForcing = p.get("First Solve Forcing", o.newton.firstSolveForcing);
  if (p.has("Predictor")) o.quadraticPredictor = p.text("Predictor") == "Quadratic";
  if (p.has("Jacobian")) o.newton.exactJacobian = p.text("Jacobian") == "Exact";
  o.newton.nox = passThrough;
  auto& entries = o.newton.nox.entries;  // Peridigm's adaptive load stepping is Periforge's to read, not NOX's
  for (auto it = entries.begin(); it != entries.end(); ++it)
    if (it->name == "Adaptive Load-Stepping") {
      if (it->kind != ParamTree::Entry::Kind::List)
        throw InputError(p.where() + ": 'Adaptive Load-Stepping' must be a list");
      o.adaptive = parseAdaptiveLoadStepping(*it->list, p);
      entries.erase(it);
      break;
    }
  o.newton.where = p.where();
  if (p.has("Nonlinear Solver")) {
    ParamTree::Entry e;
    e.name = "Nonlinear Solver";
    e.kind = ParamTree::Entry::Kind::String;
    e.text = p.text("Nonlinear Solver");
    o.newton.nox.entries.push_back(e);
  }
  checkLinearSolver(o.newton);
  o.fallback.relativeTolerance = std::max(o.newton.relativeTolerance, 1e-10);  // ADR's round-off floor is ~3e-13
  o.fallback.absoluteTolerance = o.newton.absoluteTolerance;
  return std::unique_ptr<Solver>(new NoxQuasiStaticSolver(o));
}

}  // namespace

SolverEntry NoxQuasiStaticSolver::entry() {
  SolverEntry e;
  e.name = "NOXQuasiStatic";
  e.doc = "quasi-static load steps by NOX's Newton-Krylov method (matrix-free GMRES, MueLu or Ifpack2 preconditioner)";
  e.loadSteps = true;
  e.parameters = commonSpecs(false);
  e.parameters.insert(e.parameters.begin(), S::integer("Number of Load Steps", "n: load steps from Initial to Final Time").need().atLeast(1));
  e.parameters.push_back(S::integer("Max Solver Iterations", "Peridigm's name for `Maximum Solver Iterations`").atLeast(1));
  e.parameters.push_back(S::integer("Maximum Load Step Cuts", "a failing step is halved at most this many times, then "
                                                              "relaxed by ADR").byDefault("4").nonNegative());
  e.parameters.push_back(S::text("Nonlinear Solver", "NOX's (default `Line Search Based`); checked against the names NOX builds, as are "
                                                  "`Direction`/`Method` and `Line Search`/`Method`"));
  e.parameters.push_back(S::real("Preconditioner Bond Radius", "the preconditioner keeps bonds up to this many shortest "
                                                               "bonds long; default 3 when every block is 2D, 2 when "
                                                               "any is 3D (faster there: docs/benchmark-log.md, 'Preconditioner bond radius')").atLeast(1));
  e.parameters.push_back(S::real("First Solve Forcing", "with the adaptive Krylov tolerance: the first Newton solve of "
                                                        "a step asks for no less than this times the residual "
                                                        "contraction of the previous step's first Newton iteration; "
                                                        "0: off (docs/benchmark-log.md, session 32)")
                             .byDefault("0").nonNegative());
  e.parameters.push_back(S::text("Predictor", "each load step's starting guess for the free dofs: `Linear` = the last "
                                              "increment scaled to this step's prescribed one; "
                                              "`Quadratic` = through the last three solved states where the "
                                              "prescribed dofs keep one line and direction (large-displacement "
                                              "elastic steps start converged: docs/benchmark-log.md, session 33)")
                             .oneOf({"Linear", "Quadratic"}).byDefault("Linear"));
  e.parameters.push_back(S::text("Jacobian", "the Krylov operator: `Exact` = the materials' directional derivative "
                                             "(consistent tangent of the plastic models) where every block's material "
                                             "has one, else a forward difference; `Finite Difference` = always the "
                                             "forward difference of the force (for comparisons)")
                             .oneOf({"Exact", "Finite Difference"}).byDefault("Exact"));
  e.mayAlsoSolve = {"Temperature"};
  e.passThrough = {"Direction", "Line Search", "Printing", "Solver Options"};
  e.create = [](const ParameterValues& p, const ParamTree& pass) { return create(p, pass, false); };
  return e;
}

SolverEntry NoxQuasiStaticSolver::peridigmEntry() {
  SolverEntry e;
  e.name = "QuasiStatic";
  e.doc = "Peridigm's implicit quasi-static solver; served by the NOXQuasiStatic engine";
  e.loadSteps = true;
  e.parameters = commonSpecs(true);
  e.parameters.insert(e.parameters.begin(),
                      S::integer("Number of Load Steps", "n, with the list's `Final Time` (else the `Time Steps` list)").atLeast(1));
  e.parameters.insert(e.parameters.begin() + 1, S::text("Time Steps", "the load times, the first being the initial time"));
  e.parameters.push_back(S::text("Belos Linear Solver", "Peridigm's Krylov method; accepted, Periforge's is GMRES (each "
                                                        "step converges to the same tolerance)")
                             .oneOf({"BlockCG", "BlockGmres", "Block CG", "Block GMRES", "GMRES", "CG"}));
  e.mayAlsoSolve = {"Temperature"};
  e.passThrough = {"Adaptive Load-Stepping"};
  e.create = [](const ParameterValues& p, const ParamTree& pass) { return create(p, pass, true); };
  return e;
}

}  // namespace pf
