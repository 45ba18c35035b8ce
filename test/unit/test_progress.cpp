#include <gtest/gtest.h>

#include "solvers/Progress.hpp"

namespace pf {

// The estimate is elapsed x (total - done) / done: 10 s for a quarter of the steps leaves 30 s.
TEST(ProgressTimeLeft, ScalesTheElapsedTimeByTheStepsLeft) {
  EXPECT_EQ(timeLeftText(10.0, 25, 100), "  left ~30 s");
  EXPECT_EQ(timeLeftText(13.31, 1080, 1200), "  left ~1 s");  // the example line: 13.31 x 120 / 1080
}

TEST(ProgressTimeLeft, LongEstimatesInMinutesAndHours) {
  EXPECT_EQ(timeLeftText(60.0, 1, 10), "  left ~9 min");     // 540 s
  EXPECT_EQ(timeLeftText(3600.0, 1, 4), "  left ~3.0 h");    // 10800 s
}

TEST(ProgressTimeLeft, TheLastStepAndNoStepsLeaveNothing) {
  EXPECT_EQ(timeLeftText(5.0, 10, 10), "  left 0 s");
  EXPECT_EQ(timeLeftText(5.0, 0, 10), "  left 0 s");  // no pace yet: no made-up estimate
}

// After a restart the clock counts only this run's steps: 2 s for steps 51..60 of 100 leaves 8 s (40 x 2 / 10),
// not the 1 s that counting the first run's 50 steps as done in no time would give (40 x 2 / 60).
TEST(ProgressTimeLeft, ARestartedRunCountsItsOwnSteps) {
  const ProgressClock clock(51, 100);
  EXPECT_EQ(clock.leftAfter(60, 2.0), "  left ~8 s");
  EXPECT_EQ(clock.leftAfter(100, 9.0), "  left 0 s");
  EXPECT_EQ(ProgressClock(1, 100).leftAfter(10, 2.0), "  left ~18 s");
}

}  // namespace pf
