// The list of solvers by the name of their sub-list in a "Solver" list; the types are in
// core/SolverEntry.hpp. Adding a solver = its file pair in src/solvers plus one line here.
#include "core/SolverEntry.hpp"

#include "AdrSolver.hpp"
#include "ImplicitDiffusionSolver.hpp"
#include "ImplicitSolver.hpp"
#include "NoxQuasiStaticSolver.hpp"
#include "VerletSolver.hpp"

namespace pf {

const std::vector<SolverEntry>& solverRegistry() {
  static const std::vector<SolverEntry> entries = {
      VerletSolver::entry(),
      AdrSolver::entry(),
      NoxQuasiStaticSolver::peridigmEntry(),
      NoxQuasiStaticSolver::entry(),
      ImplicitSolver::entry(),
      ImplicitDiffusionSolver::entry(),
  };
  return entries;
}

}  // namespace pf
