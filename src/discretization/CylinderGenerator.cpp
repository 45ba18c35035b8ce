#include "CylinderGenerator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/InputError.hpp"

namespace pf {

namespace {

// n = value / dx, refused unless a whole number >= 1 (a cell-centred lattice cannot end on a fraction);
// what: how the message names the value.
long wholeCells(double value, double dx, const std::string& what, const std::string& inputFile) {
  const double ratio = value / dx;
  const long n = std::lround(ratio);
  if (n < 1 || std::fabs(ratio - n) > 1e-6 * std::max(1.0, ratio)) {
    std::ostringstream msg;
    msg << inputFile << ": Discretization: " << what << " (" << value << ") is not a multiple of 'Spacing' (" << dx
        << ")";
    throw InputError(msg.str());
  }
  return n;
}

}  // namespace

long cylinderLayers(const DiscretizationSpec& d, const std::string& inputFile) {
  return wholeCells(d.cylinderLength, d.spacing, "'Length'", inputFile);
}

std::vector<std::array<double, 2>> cylinderSection(const DiscretizationSpec& d, const std::string& inputFile) {
  const double dx = d.spacing, r = d.radius;
  const long n = wholeCells(2.0 * r, dx, "the diameter 2 x 'Radius'", inputFile);
  std::vector<std::array<double, 2>> out;
  // Centres on the square grid symmetric about the axis; the relative slack keeps a centre exactly on
  // the circle (round-off must not decide it).
  for (long j = 0; j < n; ++j)
    for (long i = 0; i < n; ++i) {
      const double a = (i + 0.5) * dx - r, b = (j + 0.5) * dx - r;
      if (a * a + b * b <= r * r * (1.0 + 1e-12)) out.push_back({a, b});
    }
  return out;
}

void cylinder(const DiscretizationSpec& d, const std::string& inputFile, PointSink& sink) {
  const double dx = d.spacing;
  const long layers = cylinderLayers(d, inputFile);
  const std::vector<std::array<double, 2>> section = cylinderSection(d, inputFile);
  const int ax = d.cylinderAxis, p = (ax + 1) % 3, q = (ax + 2) % 3;  // (p, q, ax) right-handed
  PointCloud& c = sink.cloud;
  c.spacing = dx;
  c.cell = {dx, dx, dx};
  const double vol = dx * dx * dx;
  for (long k = 0; k < layers; ++k)  // base face first: the impact face of a Taylor bar holds the lowest ids
    for (const std::array<double, 2>& s : section) {
      std::array<double, 3> x = d.origin;
      x[ax] += (k + 0.5) * dx;
      x[p] += s[0];
      x[q] += s[1];
      sink.push(x[0], x[1], x[2], vol, 1);
    }
}

}  // namespace pf
