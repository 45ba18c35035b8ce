#pragma once
// Test helper: the linearised force of a lattice body and the largest real part of its eigenvalues (a growing or
// zero-energy mode shows as a value >= 0), and a lattice plate with a circular hole (a staircase). Header-only;
// used by the surface band and bond-associated stability tests. Units of the caller; the plate is centred on 0.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "LatticeFixture.hpp"

namespace pftest {

// n x n points (spacing dx, centred on the origin; layers > 1: that many z layers, a 3D slab) minus a circular
// hole of radius r about the z axis (points with |(x, y)| < r removed, as Rectangle With Holes does), families
// with horizon ratio * dx built as makeLattice builds them, influence 1.
inline Lattice latticeWithHole(int n, double r, double dx, double ratio, int layers = 1) {
  Lattice L;
  L.planar = layers <= 1, L.dx = dx, L.horizon = ratio * dx, L.thickness = dx;
  const double o = 0.5 * (n - 1), oz = 0.5 * (std::max(layers, 1) - 1);
  for (int k = 0; k < std::max(layers, 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i - o) * dx, y = (j - o) * dx;
        if (std::hypot(x, y) < r * (1 - 1e-12)) continue;
        L.x.insert(L.x.end(), {x, y, L.planar ? 0.0 : (k - oz) * dx});
        ++L.numNodes;
      }
  L.numQueries = L.numNodes;
  L.volume.assign(L.numNodes, L.nodeVolume());
  std::vector<double> candidates(L.x);
  if (L.planar) candidates.insert(candidates.end(), {0.0, 0.0, 2.0 * L.horizon + dx});  // makeLattice's workaround
  pf::buildFamilies(candidates, L.numQueries, std::vector<double>(L.numQueries, L.horizon), L.fam);
  L.fam.numNodes = L.numNodes;
  L.fam.influence.assign(L.fam.numBonds(), 1.0);
  L.m.assign(L.numQueries, 0.0);
  pf::computeWeightedVolume(L.view(), L.m.data());
  return L;
}

using ForceOf = std::function<std::vector<double>(const std::vector<double>& y)>;

// Largest real part of the eigenvalues of df/du, relative to the largest eigenvalue magnitude (central differences
// at the reference state, step h). Dofs: x and y (planar) or x, y, z per point. clamped: the bottom row's
// (y = min) dofs are removed; else the biaxial test's supports (planar: top and bottom y, one bottom point's x).
// where (optional): the point where the top mode's amplitude is largest.
inline double largestRealPart(const Lattice& L, const ForceOf& force, bool clamped, double* where = nullptr,
                              double h = 1e-9) {
  std::vector<int> dofs;
  double ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for (int p = 0; p < L.numNodes; ++p) ymin = std::min(ymin, L.x[3 * p + 1]), ymax = std::max(ymax, L.x[3 * p + 1]);
  const double half = 0.5 * L.dx;
  const int dims = L.planar ? 2 : 3;
  for (int p = 0; p < L.numNodes; ++p) {
    const double x = L.x[3 * p], y = L.x[3 * p + 1];
    if (clamped) {
      if (y > ymin + half)
        for (int d = 0; d < dims; ++d) dofs.push_back(3 * p + d);
    } else {
      if (!(y < ymin + half && std::fabs(x) < 1e-9)) dofs.push_back(3 * p);
      if (y > ymin + half && y < ymax - half) dofs.push_back(3 * p + 1);
    }
  }
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd J(n, n);
  for (int c = 0; c < n; ++c) {
    std::vector<double> yp(L.x), ym(L.x);
    yp[dofs[c]] += h, ym[dofs[c]] -= h;
    const std::vector<double> fp = force(yp), fm = force(ym);
    for (int r = 0; r < n; ++r) J(r, c) = (fp[dofs[r]] - fm[dofs[r]]) / (2 * h);
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, where != nullptr);
  const Eigen::VectorXcd ev = es.eigenvalues();
  double re = -HUGE_VAL, mag = 0;
  int top = 0;
  for (int k = 0; k < n; ++k) {
    if (ev[k].real() > re) top = k;
    re = std::max(re, ev[k].real()), mag = std::max(mag, std::abs(ev[k]));
  }
  if (where) {
    const Eigen::VectorXcd v = es.eigenvectors().col(top);
    int r = 0;
    for (int k = 0; k < n; ++k)
      if (std::abs(v[k]) > std::abs(v[r])) r = k;
    for (int d = 0; d < 3; ++d) where[d] = L.x[dofs[r] - dofs[r] % 3 + d];
  }
  return re / mag;
}

}  // namespace pftest
