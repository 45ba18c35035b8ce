#include "PressureLoad.hpp"

#include <cmath>
#include <cstdio>

#include "core/InputError.hpp"
#include "parallel/Collective.hpp"

namespace pf {

namespace {

// Below this ratio |sum xi V| / sum |xi| V the neighbours surround the point: it is inside the body, and
// the direction would be noise. A point on a flat face of a lattice with delta = 3 dx has about 0.4.
constexpr double kSurfaceRatio = 0.05;

// Unit direction into the material at owned node i, or throws naming the point.
void inwardDirection(const Model& model, int i, double d[3], const std::string& context) {
  const BondFamily& f = model.layout().family();
  const std::vector<double>& x = model.coordinates();
  const std::vector<double>& vol = model.volume();
  double s[3] = {0, 0, 0}, total = 0.0;
  for (int b = f.offsets[i]; b < f.offsets[i + 1]; ++b) {
    const int j = f.neighbors[b];
    for (int c = 0; c < 3; ++c) s[c] += (x[3 * j + c] - x[3 * i + c]) * vol[j];
    total += f.refLength[b] * vol[j];
  }
  const double norm = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  if (!(norm > kSurfaceRatio * total)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, ": point %d (%g, %g, %g) is not on a surface: its neighbours surround it",
                  model.layout().gids()[i] + 1, x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    throw InputError(context + msg);
  }
  for (int c = 0; c < 3; ++c) d[c] = s[c] / norm;
}

}  // namespace

std::vector<NodalLoad> pressureLoads(const Model& model, const std::vector<int>& nodes,
                                     std::shared_ptr<const Expression> pressure, double layerThickness,
                                     const std::string& context) {
  std::vector<NodalLoad> loads(3);
  for (int c = 0; c < 3; ++c) {
    loads[c].coordinate = c;
    loads[c].value = pressure;
  }
  collectively(model.layout().comm(), [&] {
    for (int i : nodes) {
      double d[3];
      inwardDirection(model, i, d, context);
      for (int c = 0; c < 3; ++c) {
        if (d[c] == 0.0) continue;  // a component that is exactly zero costs nothing to skip
        loads[c].nodes.push_back(i);
        loads[c].factor.push_back(d[c] / layerThickness);
      }
    }
  });
  return loads;
}

}  // namespace pf
