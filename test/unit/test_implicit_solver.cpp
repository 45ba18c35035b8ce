// The Implicit solver's entry and step count against Peridigm's conventions (executeImplicit: nsteps =
// floor((Final Time - Initial Time) / dt); Beta, Gamma defaults 0.25, 0.5) and Newmark's stability ranges.
#include <gtest/gtest.h>

#include "core/Parameters.hpp"
#include "core/SolverEntry.hpp"
#include "solvers/ImplicitSolver.hpp"

namespace {

const pf::ParameterSpec& spec(const pf::SolverEntry& e, const std::string& name) {
  for (const pf::ParameterSpec& s : e.parameters)
    if (s.name == name) return s;
  throw std::logic_error("no parameter " + name);
}

TEST(ImplicitSolver, StepCountIsPeridigmsFloorForgivingTheQuotientsRoundOff) {
  // 5e-5 / 1e-5 and 1.6e-3 / 2e-5 are not exact in binary; Peridigm's decks mean 5 and 80 steps.
  EXPECT_EQ(pf::ImplicitSolver::stepCount(0.0, 5.0e-5, 1.0e-5), 5);
  EXPECT_EQ(pf::ImplicitSolver::stepCount(0.0, 1.6e-3, 2.0e-5), 80);
  EXPECT_EQ(pf::ImplicitSolver::stepCount(0.0, 0.3, 0.1), 3);      // 0.3 / 0.1 = 2.9999999999999996
  EXPECT_EQ(pf::ImplicitSolver::stepCount(1.0, 1.35, 0.1), 3);     // not a multiple: floor, as Peridigm
  EXPECT_EQ(pf::ImplicitSolver::stepCount(0.0, 0.05, 0.1), 0);     // no step (the solver refuses it)
}

TEST(ImplicitSolver, EntryDeclaresPeridigmsNamesDefaultsAndNewmarksRanges) {
  const pf::SolverEntry* e = pf::findSolver("Implicit");
  ASSERT_NE(e, nullptr);
  EXPECT_TRUE(e->dynamic);
  EXPECT_FALSE(e->loadSteps);
  EXPECT_TRUE(spec(*e, "Fixed dt").required);
  EXPECT_EQ(spec(*e, "Beta").defaultValue, "0.25");
  EXPECT_EQ(spec(*e, "Gamma").defaultValue, "0.5");
  EXPECT_EQ(spec(*e, "Absolute Tolerance").defaultValue, "1e-6");
  EXPECT_EQ(spec(*e, "Maximum Solver Iterations").defaultValue, "10");
  // Peridigm's executeImplicit starts from a = 0 (its gold for a deck with an initial force needs it)
  EXPECT_EQ(spec(*e, "Initial Acceleration").defaultValue, "Zero");
  // Beta in (0, 1/2]: 0 would be the explicit central difference (not this solver), above 1/2 not Newmark's
  // second-order family; Gamma >= 1/2 (below it the scheme amplifies every mode).
  const pf::ParameterSpec& beta = spec(*e, "Beta");
  EXPECT_NE(beta.rangeError(0.0), "");
  EXPECT_EQ(beta.rangeError(1e-9), "");
  EXPECT_EQ(beta.rangeError(0.5), "");
  EXPECT_NE(beta.rangeError(0.5000001), "");
  EXPECT_EQ(spec(*e, "Gamma").rangeError(0.5), "");
  EXPECT_NE(spec(*e, "Gamma").rangeError(0.4999), "");
}

}  // namespace
