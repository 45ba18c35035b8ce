#pragma once
#include <chrono>
#include <string>

namespace pf {

// The estimate of the wall time left after `done` of `total` steps took `elapsed` seconds, as the text the solvers'
// progress lines end with ("  left ~12 s"). The steps so far set the pace: a run whose steps slow down (yielding,
// more Newton iterations) is underestimated until its pace settles. It is appended after "wall X s" because scripts
// parse the line up to there (scripts/bench: "step (\d+)/(\d+) .* wall ([\d.]+) s").
std::string timeLeftText(double elapsed, long done, long total);

// A run's clock for that estimate: started before the run's first step (after a restart the checkpoint's step + 1,
// so the steps of the earlier run do not count as done in no time).
class ProgressClock {
 public:
  ProgressClock(long firstStep, long lastStep)
      : first_(firstStep), last_(lastStep), start_(std::chrono::steady_clock::now()) {}
  // Seconds since the clock started.
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  // The estimate once `step` is done.
  std::string leftAfter(long step) const { return leftAfter(step, elapsed()); }
  // The same after `seconds` of this run (tests).
  std::string leftAfter(long step, double seconds) const {
    return timeLeftText(seconds, step - first_ + 1, last_ - first_ + 1);
  }

 private:
  long first_, last_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace pf
