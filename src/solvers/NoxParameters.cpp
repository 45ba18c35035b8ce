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
  if (method != "GMRES") throw InputError(at + "'Aztec Solver' = '" + method + "': only GMRES is available");
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

// One selector of NOX's factories must be a name this engine can run. An unknown name would throw from inside
// the first Newton solve, which the solver took for a failed step: every step then fell back to ADR and the
// run ended "done" (issue 40). Names NOX 13.2 builds but this engine cannot serve are refused with the reason:
// the matrix-free group applies J and a preconditioned J^-1, never J^T (steepest descent, trust regions,
// More'-Thuente's gradient, Broyden's J^-1 update); Pseudo-Transient needs a Thyra model evaluator and Safeguarded
// Step user bounds; Single Step has no convergence test (every step would end unconverged).
struct Choice {
  std::vector<std::string> valid;
  std::vector<std::pair<std::string, std::string>> refused;  // NOX's name, why this engine cannot run it
};

std::string joinQuoted(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

void requireChoice(const Teuchos::ParameterList& l, const std::string& name, const Choice& c, const std::string& at) {
  if (!l.isParameter(name)) return;
  if (!l.isType<std::string>(name)) throw InputError(at + "'" + name + "' must be a string, one of " + joinQuoted(c.valid));
  const std::string v = l.get<std::string>(name);
  if (std::find(c.valid.begin(), c.valid.end(), v) != c.valid.end()) return;
  for (const auto& [refused, why] : c.refused)
    if (v == refused)
      throw InputError(at + "'" + name + "' = '" + v + "' " + why + "; use " + joinQuoted(c.valid));
  throw InputError(at + "'" + name + "' = '" + v + "' is not one of NOX's that this engine runs: " + joinQuoted(c.valid));
}

const char* kNeedsTranspose = "needs the transposed Jacobian, which the matrix-free engine does not apply";

}  // namespace

void checkLinearSolver(const NewtonKrylovOptions& opt) {
  bool adaptive = false;
  auto params = noxParameters(opt, 0, &adaptive);
  requireChoice(*params, "Nonlinear Solver",
                {{"Line Search Based", "Newton", "Anderson Accelerated Fixed-Point"},
                 {{"Trust Region Based", kNeedsTranspose},
                  {"Inexact Trust Region Based", kNeedsTranspose},
                  {"Tensor Based", "needs NOX's tensor line searches and the transposed Jacobian"},
                  {"Pseudo-Transient", "needs a Thyra model evaluator, not this engine's group"},
                  {"Single Step", "takes one Newton step without a convergence test (every load step would fail)"}}},
                opt.where + ": ");
  requireChoice(params->sublist("Direction"), "Method",
                {{"Newton", "NonlinearCG"},
                 {{"Steepest Descent", kNeedsTranspose},
                  {"Broyden", "needs the inverse Jacobian's update, which the matrix-free engine does not hold"}}},
                opt.where + "/Direction: ");
  requireChoice(params->sublist("Line Search"), "Method",
                {{"Full Step", "Backtrack", "Polynomial", "NonlinearCG"},
                 {{"More'-Thuente", "needs the merit function's gradient (the transposed Jacobian)"},
                  {"Safeguarded Step", "needs user-defined bounds no deck can give"}}},
                opt.where + "/Line Search: ");
  linearSolverChoice(params->sublist("Direction").sublist("Newton").sublist("Linear Solver"), opt.where);
}

}  // namespace pf
