#include "NoxParameters.hpp"

#include <NOX_Utils.H>

#include <algorithm>
#include <vector>

#include "core/InputError.hpp"

namespace pf {

namespace {

// The deck's NOX options as NOX reads them.
Teuchos::ParameterList teuchosOf(const ParamTree& tree) {
  Teuchos::ParameterList l;
  for (const ParamTree::Entry& e : tree.entries) {
    switch (e.kind) {
      case ParamTree::Entry::Kind::Double: l.set(e.name, e.number); break;
      case ParamTree::Entry::Kind::Int: l.set(e.name, e.integer); break;
      case ParamTree::Entry::Kind::Bool: l.set(e.name, e.flag); break;
      case ParamTree::Entry::Kind::String: l.set(e.name, e.text); break;
      case ParamTree::Entry::Kind::List: l.set(e.name, teuchosOf(*e.list)); break;
    }
  }
  return l;
}

}  // namespace

// NOX's parameters: the deck's, with Periforge's defaults where the deck is silent. *adaptiveTolerance:
// the deck set no Krylov "Tolerance" (each solve then asks for what the force test still needs).
Teuchos::RCP<Teuchos::ParameterList> noxParameters(const NewtonKrylovOptions& opt, int rank, bool* adaptiveTolerance) {
  auto params = Teuchos::rcp(new Teuchos::ParameterList(teuchosOf(opt.nox)));
  setDefault(*params, "Nonlinear Solver", "Line Search Based");
  Teuchos::ParameterList& print = params->sublist("Printing");
  // Same on every rank: NOX computes the norms it prints collectively and prints on Output Processor.
  setDefault(print, "Output Information",
             opt.verbose ? NOX::Utils::OuterIteration + NOX::Utils::OuterIterationStatusTest + NOX::Utils::Warning
                         : NOX::Utils::Error);
  setDefault(print, "MyPID", rank);
  setDefault(print, "Output Processor", 0);
  Teuchos::ParameterList& dir = params->sublist("Direction");
  setDefault(dir, "Method", "Newton");
  Teuchos::ParameterList& ls = dir.sublist("Newton").sublist("Linear Solver");
  setDefault(ls, "Aztec Solver", "GMRES");
  setDefault(ls, "Max Iterations", 800);
  *adaptiveTolerance = !ls.isParameter("Tolerance");  // a deck's own Tolerance is kept fixed
  setDefault(ls, "Tolerance", 1e-9);
  setDefault(ls, "Size of Krylov Subspace", 200);
  setDefault(ls, "Preconditioner", "ML");
  setDefault(params->sublist("Line Search"), "Method", "Polynomial");
  return params;
}

LinearSolverChoice linearSolverChoice(Teuchos::ParameterList& ls, const std::string& where) {
  const std::string at = where + "/Direction/Newton/Linear Solver: ";
  LinearSolverChoice c;
  const std::string method = ls.get<std::string>("Aztec Solver", "GMRES");
  if (method != "GMRES") throw InputError(at + "'Aztec Solver' = '" + method + "': only GMRES (Belos) is available");
  const std::string type = ls.get<std::string>("Preconditioner", "ML");
  if (type == "ML" || type == "MueLu") {
    c.preconditioner = LinearSolverChoice::Preconditioner::MueLu;
    if (ls.isSublist("ML"))
      throw InputError(at + "the 'ML' sub-list is not read since ML gave way to MueLu (issue 20); give MueLu's "
                       "parameter names in a 'MueLu' sub-list");
  } else if (type == "AztecOO") {
    // Peridigm's "AztecOO": AztecOO's own domain-decomposition ILU, which Ifpack2's RILUK replaces.
    c.preconditioner = LinearSolverChoice::Preconditioner::Ifpack2;
    c.ifpack2Type = "RILUK";
  } else if (type == "New Ifpack" || type == "Ifpack2") {
    c.preconditioner = LinearSolverChoice::Preconditioner::Ifpack2;
    c.ifpack2Type = ls.get<std::string>("Ifpack Preconditioner", "ILU");
    if (c.ifpack2Type == "ILU") c.ifpack2Type = "RILUK";
    if (c.ifpack2Type != "RILUK" && c.ifpack2Type != "ILUT" && c.ifpack2Type != "RELAXATION" &&
        c.ifpack2Type != "CHEBYSHEV")
      throw InputError(at + "'Ifpack Preconditioner' = '" + c.ifpack2Type +
                       "': use ILU, ILUT, RELAXATION or CHEBYSHEV (Ifpack2's)");
  } else if (type == "None") {
    c.preconditioner = LinearSolverChoice::Preconditioner::None;
  } else {
    throw InputError(at + "'Preconditioner' = '" + type + "': use ML (MueLu), New Ifpack (Ifpack2), AztecOO (Ifpack2's ILU) or None");
  }
  return c;
}

namespace {

// One selector of NOX's factories must be one of the names it builds (NOX 13.2's Solver, Direction and
// LineSearch factories). An unknown name would throw from inside the first Newton solve, which the solver
// takes for a failed step: every step would then fall back to ADR and the run end "done" (issue 40).
// "User Defined" needs a factory object no deck can give, and the prerelease directions are not built.
std::string joinQuoted(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

void requireChoice(const Teuchos::ParameterList& l, const std::string& name, const std::vector<std::string>& valid,
                   const std::string& at) {
  if (!l.isParameter(name)) return;
  if (!l.isType<std::string>(name)) throw InputError(at + "'" + name + "' must be a string, one of " + joinQuoted(valid));
  const std::string v = l.get<std::string>(name);
  if (std::find(valid.begin(), valid.end(), v) == valid.end())
    throw InputError(at + "'" + name + "' = '" + v + "' is not one of NOX's: " + joinQuoted(valid));
}

}  // namespace

void checkLinearSolver(const NewtonKrylovOptions& opt) {
  bool adaptive = false;
  auto params = noxParameters(opt, 0, &adaptive);
  requireChoice(*params, "Nonlinear Solver",
                {"Line Search Based", "Newton", "Trust Region Based", "Inexact Trust Region Based", "Tensor Based",
                 "Anderson Accelerated Fixed-Point", "Single Step", "Pseudo-Transient"},
                opt.where + ": ");
  requireChoice(params->sublist("Direction"), "Method", {"Newton", "Steepest Descent", "NonlinearCG", "Broyden"},
                opt.where + "/Direction: ");
  requireChoice(params->sublist("Line Search"), "Method",
                {"Full Step", "Backtrack", "Polynomial", "More'-Thuente", "NonlinearCG", "Safeguarded Step"},
                opt.where + "/Line Search: ");
  linearSolverChoice(params->sublist("Direction").sublist("Newton").sublist("Linear Solver"), opt.where);
}

}  // namespace pf
