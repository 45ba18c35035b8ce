#pragma once
// Chooses and configures the solver named by the one solver sub-list of a solver list ("Solver", or one of
// Peridigm's "Solver1", "Solver2", ...; validated before). listName only labels error messages.
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

#include "Solver.hpp"

namespace pf {

// The times a solver list runs through: {Initial Time, Final Time} for Verlet; for the quasi-static
// solvers the start and the end of every load step: Initial Time + k (Final Time - Initial Time) / n for
// k = 0..n ("Number of Load Steps" = n), or, without Final Time, the QuasiStatic list's "Time Steps".
std::vector<double> solverTimes(const Teuchos::ParameterList& solverList);

std::unique_ptr<Solver> makeSolver(const Teuchos::ParameterList& solverList, const std::string& inputFile,
                                   const std::string& listName = "Solver");

}  // namespace pf
