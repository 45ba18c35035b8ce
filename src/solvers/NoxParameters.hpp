#pragma once
// Part of the NOX adapter: the Teuchos parameter list NOX reads for one Newton solve, from a deck's
// pass-through sub-lists ("Direction", "Line Search", "Printing", ...) with Periforge's defaults where the
// deck is silent (line-search Newton, GMRES, MueLu's smoothed aggregation, the preconditioner kept for the
// whole run), and the linear solver choices read from it.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

#include "NewtonKrylov.hpp"

namespace pf {

// *adaptiveTolerance: the deck set no Krylov "Tolerance" (each solve then asks for what the force test
// still needs).
Teuchos::RCP<Teuchos::ParameterList> noxParameters(const NewtonKrylovOptions& opt, int rank, bool* adaptiveTolerance);

// The deck's "Linear Solver" choices as Belos, MueLu and Ifpack2 take them. Peridigm's (AztecOO's) names are
// kept: "ML" is MueLu's smoothed aggregation, "New Ifpack" with "Ifpack Preconditioner" ILU is Ifpack2's RILUK.
struct LinearSolverChoice {
  enum class Preconditioner { MueLu, Ifpack2, None } preconditioner = Preconditioner::MueLu;
  std::string ifpack2Type;  // RILUK, ILUT, RELAXATION or CHEBYSHEV
};
// ls: the "Linear Solver" list with the defaults set; throws InputError naming where and the parameter.
LinearSolverChoice linearSolverChoice(Teuchos::ParameterList& ls, const std::string& where);

// Sets l[name] = v unless the deck gave it. Teuchos stores a const char* as std::string.
template <class T>
void setDefault(Teuchos::ParameterList& l, const std::string& name, T v) {
  if (!l.isParameter(name)) l.set(name, v);
}

}  // namespace pf
