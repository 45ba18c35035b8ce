#include "solvers/Progress.hpp"

#include <cmath>
#include <cstdio>

namespace pf {

std::string timeLeftText(double elapsed, long done, long total) {
  if (done <= 0 || total <= done || !(elapsed >= 0.0)) return "  left 0 s";
  const double left = elapsed * static_cast<double>(total - done) / static_cast<double>(done);
  char text[48];
  if (left < 99.5)
    std::snprintf(text, sizeof text, "  left ~%.0f s", left);
  else if (left < 5940.0)  // under 99 min
    std::snprintf(text, sizeof text, "  left ~%.0f min", left / 60.0);
  else
    std::snprintf(text, sizeof text, "  left ~%.1f h", left / 3600.0);
  return text;
}

}  // namespace pf
