#include "SolverFactory.hpp"

#include "core/SolverEntry.hpp"

namespace pf {

std::unique_ptr<Solver> makeSolver(const SolverSpec& spec) {
  std::unique_ptr<Solver> solver = findSolver(spec.type)->create(spec.options, spec.passThrough);  // name checked
  solver->setFields(spec.fields);
  return solver;
}

}  // namespace pf
