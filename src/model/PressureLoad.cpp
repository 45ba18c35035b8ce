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

// With the NDO band (Li & Geng Eq. 31) the outer layer's traction term is -P n / dx with n the sum of the
// point's missing axis directions, so the load must be T_ext / dx = -p n / dx with the same n, or a uniform
// stress is not in balance: at a corner of a flat face only the face's own axis counts (the axes in which
// the set has no extent: a corner of Min X is pushed along x alone); on a curved set (a staircase) every
// missing axis is an exposed cell face the pressure acts on. False (d untouched) off the outer layer.
bool bandDirection(const SurfaceBand& band, int i, const bool flat[3], bool anyFlat, double d[3]) {
  const double* n = &band.outerNormal[3 * i];
  if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0) return false;
  for (int c = 0; c < 3; ++c) d[c] = anyFlat && !flat[c] ? 0.0 : -n[c];
  return true;
}

}  // namespace

std::vector<NodalLoad> pressureLoads(const Model& model, const std::vector<int>& nodes,
                                     std::shared_ptr<const Expression> pressure, double layerThickness,
                                     const std::string& context, bool follower) {
  std::vector<NodalLoad> loads(3);
  for (int c = 0; c < 3; ++c) {
    loads[c].coordinate = c;
    loads[c].value = pressure;
  }
  // With the band: the axes in which the whole set is flat (reference extent below a quarter layer). Collective
  // (every rank has the same band or none).
  const SurfaceBand* band = model.surfaceBand();
  if (follower && !band)
    throw InputError(context + ": 'Follower' = true needs the NDO band (Blocks 'Surface Correction' = 'NDO Band'): "
                               "the deformed area comes from the band's deformation gradient");
  const std::vector<double>& x = model.coordinates();
  bool flat[3] = {false, false, false}, anyFlat = false;
  for (int c = 0; c < 3 && band; ++c) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int i : nodes) lo = std::fmin(lo, x[3 * i + c]), hi = std::fmax(hi, x[3 * i + c]);
    flat[c] = model.max(hi) + model.max(-lo) <= 0.25 * layerThickness;
    anyFlat = anyFlat || flat[c];
  }
  collectively(model.layout().comm(), [&] {
    for (int i : nodes) {
      double d[3];
      const bool onBand = band && bandDirection(*band, i, flat, anyFlat, d);
      if (follower && !onBand) {
        const std::vector<double>& xs = model.coordinates();
        char msg[240];
        std::snprintf(msg, sizeof msg,
                      ": 'Follower' = true: point %d (%g, %g, %g) is not on the NDO band's outer layer",
                      model.layout().gids()[i] + 1, xs[3 * i], xs[3 * i + 1], xs[3 * i + 2]);
        throw InputError(context + msg);
      }
      if (!onBand) inwardDirection(model, i, d, context);
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
