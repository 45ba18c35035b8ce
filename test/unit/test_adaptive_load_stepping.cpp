// Peridigm's adaptive load stepping: the times after a step is halved, and the sub-list's checks.
#include <gtest/gtest.h>

#include <vector>

#include "core/InputError.hpp"
#include "solvers/AdaptiveLoadStepping.hpp"

namespace {

using pf::ParamTree;

ParamTree::Entry integer(const char* name, int value) {
  ParamTree::Entry e;
  e.name = name;
  e.kind = ParamTree::Entry::Kind::Int;
  e.integer = value;
  return e;
}

TEST(AdaptiveLoadStepping, HalvingInsertsTheMidpointBeforeTheFailedStepsEnd) {
  std::vector<double> t = {0.0, 1.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(pf::halveStep(t, 1.0, 2.0, false), 0.5);
  EXPECT_EQ(t, (std::vector<double>{0.0, 1.0, 1.5, 2.0, 3.0}));
}

TEST(AdaptiveLoadStepping, ReducingAllRemainingStepsMakesEqualStepsToTheEnd) {
  std::vector<double> t = {0.0, 1.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(pf::halveStep(t, 1.0, 2.0, true), 0.5);
  EXPECT_EQ(t, (std::vector<double>{0.0, 1.0, 1.5, 2.0, 2.5, 3.0}));
  // A remainder that is not a whole number of half steps: equal steps no longer than the half (0.4 < 0.5).
  std::vector<double> u = {0.0, 1.0, 3.0};
  EXPECT_NEAR(pf::halveStep(u, 1.0, 3.0, true), 1.0, 1e-15);
  std::vector<double> w = {0.0, 1.0, 2.0};
  const double h = pf::halveStep(w, 0.0, 1.0, true);
  EXPECT_NEAR(h, 0.5, 1e-15);
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w.back(), 2.0);
}

TEST(AdaptiveLoadStepping, TheMaximaAreRequiredAndUnknownNamesRefused) {
  pf::ParameterValues solver;
  solver.inputFile = "d.xml";
  solver.path = "Solver/QuasiStatic";
  ParamTree list;
  list.entries.push_back(integer("Maximum total load step reductions", 5));
  EXPECT_THROW(pf::parseAdaptiveLoadStepping(list, solver), pf::InputError);
  list.entries.push_back(integer("Maximum load step reductions in one step", 1));
  const pf::AdaptiveLoadStepping a = pf::parseAdaptiveLoadStepping(list, solver);
  EXPECT_TRUE(a.on);
  EXPECT_EQ(a.maxReductionsInStep, 1);
  EXPECT_EQ(a.maxTotalReductions, 5);
  EXPECT_FALSE(a.switchToVerlet);
  list.entries.push_back(integer("Maximum reductions", 1));
  EXPECT_THROW(pf::parseAdaptiveLoadStepping(list, solver), pf::InputError);
}

}  // namespace
