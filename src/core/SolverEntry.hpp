#pragma once
// The solver registry's types: what a solver declares about itself (its sub-list name in a "Solver"
// list, its parameters, the sub-lists it passes to a library unread) and how it is built. The list is
// src/solvers/SolverRegistry.cpp; the input layer reaches it only through solverRegistry().
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ParamTree.hpp"
#include "Parameters.hpp"

namespace pf {

class Solver;

struct SolverEntry {
  std::string name;                       // the sub-list of a Solver list: "Verlet", "NOXQuasiStatic", ...
  std::string doc;
  std::vector<ParameterSpec> parameters;  // of that sub-list
  std::vector<std::string> passThrough;   // its sub-lists handed to the solver unread (a library's own)
  // Load-stepping solvers step through Initial Time + k (Final Time - Initial Time) / n, n = "Number of
  // Load Steps" (or a "Time Steps" list, where declared); the others run from Initial to Final Time.
  bool loadSteps = false;
  bool dynamic = false;  // integrates inertia: its velocities are physical and it may write Acceleration
  // The field it advances: "Displacement" (the mechanics solvers) or "Temperature" (ImplicitDiffusion). The deck's
  // Solver flags `Solve For Displacement` / `Solve For Temperature` must agree with it.
  std::string solves = "Displacement";
  // Further fields a deck may make it advance with `Solve For <field>` = true (Verlet, the quasi-static Newton
  // solvers: Temperature); with mayOmitOwn it may also leave out its own (Verlet's `Solve For Displacement` = false:
  // a thermal-only explicit run).
  std::vector<std::string> mayAlsoSolve;
  bool mayOmitOwn = false;
  std::function<std::unique_ptr<Solver>(const ParameterValues& options, const ParamTree& passThrough)> create;
};

const std::vector<SolverEntry>& solverRegistry();  // defined in src/solvers/SolverRegistry.cpp
const SolverEntry* findSolver(const std::string& name);  // nullptr if unknown

}  // namespace pf
