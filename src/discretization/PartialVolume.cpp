#include "PartialVolume.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pf {

namespace {

// Antiderivative of sqrt(R^2 - x^2) on [-R, R].
double chordIntegral(double x, double R) {
  x = std::clamp(x, -R, R);
  return 0.5 * (x * std::sqrt(std::max(R * R - x * x, 0.0)) + R * R * std::asin(x / R));
}

void addBreak(std::vector<double>& b, double x, double lo, double hi) {
  if (x > lo && x < hi) b.push_back(x);
}

// The x in (lo, hi) where the ball's section through x, radius sqrt(R^2 - x^2), has radius r.
void addSectionRadiusBreaks(std::vector<double>& b, double r, double R, double lo, double hi) {
  if (!(r < R)) return;
  const double x = std::sqrt(R * R - r * r);
  addBreak(b, x, lo, hi);
  addBreak(b, -x, lo, hi);
}

// Area of [a0, b0] x [a1, b1] inside the disk of radius R about the origin, exactly: between the
// breakpoints (where the chord half-length s(x) = sqrt(R^2 - x^2) crosses a1, b1 or 0) the overlap
// min(b1, s) - max(a1, -s) is one of b1 - a1, s - a1, b1 + s, 2s or 0, each integrated in closed form.
double rectangleInDisk(double a0, double b0, double a1, double b1, double R) {
  if (R <= 0.0 || a0 >= R || b0 <= -R) return 0.0;
  std::vector<double> br = {a0, b0};
  addBreak(br, -R, a0, b0);
  addBreak(br, R, a0, b0);
  for (double c : {a1, b1}) addSectionRadiusBreaks(br, std::fabs(c), R, a0, b0);
  std::sort(br.begin(), br.end());
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < br.size(); ++k) {
    const double p = br[k], q = br[k + 1];
    if (q <= p) continue;
    const double xm = 0.5 * (p + q);
    if (std::fabs(xm) >= R) continue;
    const double s = std::sqrt(R * R - xm * xm);
    const bool upperIsEdge = b1 < s, lowerIsEdge = a1 > -s;
    if ((upperIsEdge ? b1 : s) <= (lowerIsEdge ? a1 : -s)) continue;
    const double S = chordIntegral(q, R) - chordIntegral(p, R);
    area += (upperIsEdge ? b1 * (q - p) : S) - (lowerIsEdge ? a1 * (q - p) : -S);
  }
  return area;
}

// Volume of the box [a, b] inside the ball of radius R: the integral over x of the cross-section area
// (rectangleInDisk at radius sqrt(R^2 - x^2)), by 20-point Gauss-Legendre between the x where that
// radius reaches an edge or a corner distance of the cross-section (the kinks of the area).
double boxInBall(const double a[3], const double b[3], double R) {
  static const double gx[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271, 0.6360536807265150,
                                0.7463319064601508, 0.8391169718222188, 0.9122344282513258, 0.9639719272779138, 0.9931285991850949};
  static const double gw[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183819, 0.1316886384491765, 0.1181945319615182,
                                0.1019301198172403, 0.0832767415767047, 0.0626720483341094, 0.0406014298003862, 0.0176140071391533};
  const double lo = std::max(a[0], -R), hi = std::min(b[0], R);
  if (hi <= lo) return 0.0;
  std::vector<double> br = {lo, hi};
  std::vector<double> radii = {std::fabs(a[1]), std::fabs(b[1]), std::fabs(a[2]), std::fabs(b[2])};
  for (double c1 : {a[1], b[1]})
    for (double c2 : {a[2], b[2]}) radii.push_back(std::hypot(c1, c2));
  for (double r : radii) addSectionRadiusBreaks(br, r, R, lo, hi);
  std::sort(br.begin(), br.end());
  double vol = 0.0;
  for (std::size_t k = 0; k + 1 < br.size(); ++k) {
    const double p = br[k], q = br[k + 1], h = 0.5 * (q - p), c = 0.5 * (q + p);
    if (h <= 0.0) continue;
    for (int g = 0; g < 10; ++g)
      for (double x : {c - h * gx[g], c + h * gx[g]})
        vol += h * gw[g] * rectangleInDisk(a[1], b[1], a[2], b[2], std::sqrt(std::max(R * R - x * x, 0.0)));
  }
  return vol;
}

}  // namespace

double halfCellDiagonal(const std::array<double, 3>& cell) {
  return 0.5 * std::sqrt(cell[0] * cell[0] + cell[1] * cell[1] + cell[2] * cell[2]);
}

double cellFractionInBall(const std::array<double, 3>& d, const std::array<double, 3>& cell, double radius) {
  // Nearest and farthest points of the cell from the centre: all outside or all inside.
  double near2 = 0.0, far2 = 0.0, flat2 = 0.0;
  double a[3], b[3];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const double h = 0.5 * cell[k], ad = std::fabs(d[k]);
    near2 += std::pow(std::max(ad - h, 0.0), 2);
    far2 += std::pow(ad + h, 2);
    if (cell[k] > 0.0) {
      a[n] = d[k] - h;
      b[n] = d[k] + h;
      ++n;
    } else {
      flat2 += d[k] * d[k];
    }
  }
  const double R2 = radius * radius;
  if (near2 >= R2) return 0.0;
  if (far2 <= R2) return 1.0;
  const double R = std::sqrt(std::max(R2 - flat2, 0.0));  // radius of the ball's section through the flat axes
  double measure = 1.0;
  for (int k = 0; k < 3; ++k)
    if (cell[k] > 0.0) measure *= cell[k];
  double inside = 0.0;
  if (n == 1) inside = std::max(0.0, std::min(b[0], R) - std::max(a[0], -R));
  else if (n == 2) inside = rectangleInDisk(a[0], b[0], a[1], b[1], R);
  else if (n == 3) inside = boxInBall(a, b, R);
  else return 1.0;  // a point cell: inside (near2 < R2)
  return std::clamp(inside / measure, 0.0, 1.0);
}

double PartialVolumeTable::fraction(const std::array<double, 3>& d, double radius) {
  // Most bonds are whole cells inside: answered before the cache is consulted.
  double far2 = 0.0;
  for (int k = 0; k < 3; ++k) far2 += (std::fabs(d[k]) + 0.5 * cell_[k]) * (std::fabs(d[k]) + 0.5 * cell_[k]);
  if (far2 <= radius * radius) return 1.0;
  std::int64_t key[3] = {0, 0, 0};
  bool lattice = true;
  for (int k = 0; k < 3 && lattice; ++k) {
    if (cell_[k] > 0.0) {
      const double q = d[k] / cell_[k], r = std::round(q);
      lattice = std::fabs(q - r) < 1e-6;
      key[k] = static_cast<std::int64_t>(r);
    } else {
      lattice = std::fabs(d[k]) <= 1e-12 * radius;
    }
  }
  if (!lattice) return cellFractionInBall(d, cell_, radius);
  const auto id = std::make_tuple(radius, key[0], key[1], key[2]);
  auto it = cache_.find(id);
  if (it != cache_.end()) return it->second;
  // The exact lattice offset, so that every rank (and both ends of a bond) get the same value.
  std::array<double, 3> exact{};
  for (int k = 0; k < 3; ++k) exact[k] = cell_[k] > 0.0 ? key[k] * cell_[k] : 0.0;
  const double f = cellFractionInBall(exact, cell_, radius);
  cache_.emplace(id, f);
  return f;
}

}  // namespace pf
