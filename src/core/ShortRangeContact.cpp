#include "ShortRangeContact.hpp"

#include <cmath>

namespace pf {

namespace {

// One end's share of the force on i, as Peridigm's pass over the point `self` (i's own pass: self = i; its
// partner's: self = j) writes it, operation for operation, so that a pair's force rounds as Peridigm's does:
// the normal force temp V_j (y_i - y_j) / d, temp = c (r_c - d) / h, and friction -mu |F_n| w / |w| with w the
// tangential velocity of i relative to the pair's mean tangential velocity (normal: from self to the other point).
void addEnd(const ShortRangeForceLaw& law, double friction, const ContactPair& p, bool selfIsI, double d, double* fi) {
  const double h = selfIsI ? p.horizonI : p.horizonJ;
  const double c = 9.0 * law.springConstant / (M_PI * h * h * h * h);
  const double temp = c * (law.contactRadius - d) / h;
  const double* ySelf = selfIsI ? p.yi : p.yj;
  const double* yOther = selfIsI ? p.yj : p.yi;
  double normal[3];  // the force on i: away from j
  for (int c3 = 0; c3 < 3; ++c3)
    normal[c3] = selfIsI ? -(temp * p.volumeJ * (yOther[c3] - ySelf[c3]) / d) : temp * p.volumeJ * (yOther[c3] - ySelf[c3]) / d;
  if (friction == 0.0) {
    for (int c3 = 0; c3 < 3; ++c3) fi[c3] += normal[c3];
    return;
  }
  double n[3];
  for (int c3 = 0; c3 < 3; ++c3) n[c3] = (yOther[c3] - ySelf[c3]) / d;
  const double vin = p.vi[0] * n[0] + p.vi[1] * n[1] + p.vi[2] * n[2];
  const double vjn = p.vj[0] * n[0] + p.vj[1] * n[1] + p.vj[2] * n[2];
  double w[3];
  for (int c3 = 0; c3 < 3; ++c3) {
    const double viPerp = p.vi[c3] - vin * n[c3], vjPerp = p.vj[c3] - vjn * n[c3];
    const double mean = selfIsI ? 0.5 * (viPerp + vjPerp) : 0.5 * (vjPerp + viPerp);
    w[c3] = viPerp - mean;
  }
  const double wn = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double fn = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  for (int c3 = 0; c3 < 3; ++c3) fi[c3] += normal[c3] + (wn != 0.0 ? -friction * fn * w[c3] / wn : 0.0);
}

}  // namespace

bool addShortRangeForce(const ShortRangeForceLaw& law, double friction, const ContactPair& p, double* fi) {
  const double rc = law.contactRadius;
  const double dy[3] = {p.yi[0] - p.yj[0], p.yi[1] - p.yj[1], p.yi[2] - p.yj[2]};
  const double d2 = dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2];
  if (!(d2 < rc * rc)) return false;
  const double d = std::sqrt(d2);
  addEnd(law, friction, p, true, d, fi);
  addEnd(law, friction, p, false, d, fi);
  return true;
}

double shortRangeHalfEnergy(const ShortRangeForceLaw& law, const ContactPair& p, double volumeI) {
  const double rc = law.contactRadius;
  const double dy[3] = {p.yi[0] - p.yj[0], p.yi[1] - p.yj[1], p.yi[2] - p.yj[2]};
  const double d2 = dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2];
  if (!(d2 < rc * rc)) return 0.0;
  auto c = [&](double h) { return 9.0 * law.springConstant / (M_PI * h * h * h * h * h); };
  const double overlap = rc - std::sqrt(d2);
  return 0.25 * (c(p.horizonI) + c(p.horizonJ)) * volumeI * p.volumeJ * overlap * overlap;
}

}  // namespace pf
