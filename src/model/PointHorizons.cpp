#include "PointHorizons.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/InputError.hpp"
#include "core/Words.hpp"

namespace pf {

std::vector<double> pointHorizons(const PointCloud& points, const std::map<int, HorizonRule>& ruleOf) {
  std::vector<double> h(points.size());
  for (int p = 0; p < points.size(); ++p) {
    const HorizonRule& r = ruleOf.at(points.block[p]);
    if (!r.expression) {
      h[p] = r.constant;
      continue;
    }
    const double* x = &points.x[3 * p];
    h[p] = (*r.expression)(x[0], x[1], x[2], 0.0);
    if (h[p] > 0.0 && std::isfinite(h[p])) continue;
    // Peridigm stops too (ProximitySearch: "search radii must be greater than zero"), naming neither block nor point.
    const std::string why = r.expression->whyNotFinite(x[0], x[1], x[2], 0.0);
    char at[200];
    std::snprintf(at, sizeof at, " is %g at the point (%g, %g, %g) of block_%d", h[p], x[0], x[1], x[2],
                  points.block[p]);
    throw InputError(r.where + ": 'Horizon' = '" + oneLine(r.expression->text()) + "'" + at +
                     (why.empty() ? std::string() : " (" + why + ")") + "; a horizon must be positive and finite");
  }
  return h;
}

bool uniformHorizon(const std::vector<double>& horizon, const Communicator& comm) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double h : horizon) lo = std::min(lo, h), hi = std::max(hi, h);
  const double largest = comm.max(hi), smallest = -comm.max(-lo);
  return largest == -HUGE_VAL || smallest == largest;  // no point at all, or one value
}

}  // namespace pf
