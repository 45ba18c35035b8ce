#include "NoxParameters.hpp"

#include <NOX_Utils.H>

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
  setDefault(ls, "Preconditioner Reuse Policy", "Reuse");
  setDefault(ls, "Max Age Of Prec", 1000000);
  setDefault(ls, "Output Frequency", 0);
  setDefault(params->sublist("Line Search"), "Method", "Polynomial");
  return params;
}

}  // namespace pf
