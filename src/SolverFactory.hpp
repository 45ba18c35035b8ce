#pragma once
// Chooses and configures the solver named by the one solver sub-list of "Solver" (validated before).
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>

#include "Solver.hpp"

namespace pf {

std::unique_ptr<Solver> makeSolver(const Teuchos::ParameterList& solverList, const std::string& inputFile);

}  // namespace pf
