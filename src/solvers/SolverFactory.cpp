#include "SolverFactory.hpp"

#include "core/SolverEntry.hpp"

namespace pf {

std::unique_ptr<Solver> makeSolver(const SolverSpec& spec) {
  return findSolver(spec.type)->create(spec.options, spec.passThrough);  // the input layer checked the name
}

}  // namespace pf
