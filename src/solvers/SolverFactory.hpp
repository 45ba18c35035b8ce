#pragma once
// Builds the solver a validated SolverSpec names, through the solver registry (SolverRegistry.cpp).
#include <memory>

#include "Solver.hpp"
#include "input/Deck.hpp"

namespace pf {

std::unique_ptr<Solver> makeSolver(const SolverSpec& spec);

}  // namespace pf
