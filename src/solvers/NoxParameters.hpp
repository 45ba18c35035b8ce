#pragma once
// Part of the NOX adapter: the Teuchos parameter list NOX reads for one Newton solve, from a deck's
// pass-through sub-lists ("Direction", "Line Search", "Printing", ...) with Periforge's defaults where the
// deck is silent (line-search Newton, GMRES, ML, the preconditioner kept for the whole run).
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

#include "NewtonKrylov.hpp"

namespace pf {

// *adaptiveTolerance: the deck set no Krylov "Tolerance" (each solve then asks for what the force test
// still needs).
Teuchos::RCP<Teuchos::ParameterList> noxParameters(const NewtonKrylovOptions& opt, int rank, bool* adaptiveTolerance);

// Sets l[name] = v unless the deck gave it. Teuchos stores a const char* as std::string.
template <class T>
void setDefault(Teuchos::ParameterList& l, const std::string& name, T v) {
  if (!l.isParameter(name)) l.set(name, v);
}

}  // namespace pf
