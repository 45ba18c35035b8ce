#include "SolverEntry.hpp"

namespace pf {

const SolverEntry* findSolver(const std::string& name) {
  for (const SolverEntry& e : solverRegistry())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace pf
