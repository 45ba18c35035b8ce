#pragma once
// Test helper: a regular lattice (3D cube, or 2D square slab at z = 0 with thickness h) centred on the
// origin, with its families built by pf::buildFamilies, influence values, nodal volumes and weighted
// volumes, plus a hand-built ElasticMaterial. Header-only; used by the material unit tests.
#include <cmath>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "core/BondFamily.hpp"
#include "materials/ElasticMaterial.hpp"
#include "core/InfluenceFunction.hpp"
#include "core/MaterialEntry.hpp"
#include "discretization/NeighborSearch.hpp"

namespace pftest {

struct Lattice {
  int numNodes = 0;   // all lattice points
  int numQueries = 0; // nodes whose families are built (all, or only node 0 = the centre)
  bool planar = false;
  double dx = 0, horizon = 0, thickness = 0;
  std::vector<double> x, volume, m;
  pf::BondFamily fam;

  pf::FamilyView view(int begin, int end) const {
    return pf::makeView(fam, begin, end, x.data(), volume.data(), m.data(), horizon);
  }
  pf::FamilyView view() const { return view(0, numQueries); }
  double nodeVolume() const { return planar ? dx * dx * thickness : dx * dx * dx; }
};

// n points per direction (n x n x n, or n x n x 1 when planar), spacing dx, horizon = ratio * dx.
// centreOnly: the centre point is moved to index 0 and only its family is built (numQueries = 1) --
// enough for interior-point checks on large horizons. n should be odd so that the centre is a node.
inline Lattice makeLattice(int n, bool planar, double dx, double ratio, double thickness,
                           pf::Influence infl, bool centreOnly) {
  Lattice L;
  L.planar = planar;
  L.dx = dx;
  L.horizon = ratio * dx;
  L.thickness = thickness;
  const int nz = planar ? 1 : n;
  const double o = 0.5 * (n - 1);
  int centre = -1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double p[3] = {(i - o) * dx, (j - o) * dx, planar ? 0.0 : (k - o) * dx};
        if (std::fabs(p[0]) < 1e-3 * dx && std::fabs(p[1]) < 1e-3 * dx && std::fabs(p[2]) < 1e-3 * dx)
          centre = L.numNodes;
        L.x.insert(L.x.end(), p, p + 3);
        ++L.numNodes;
      }
  if (centreOnly && centre > 0)
    for (int d = 0; d < 3; ++d) std::swap(L.x[d], L.x[3 * centre + d]);
  L.numQueries = centreOnly ? 1 : L.numNodes;
  L.volume.assign(L.numNodes, L.nodeVolume());
  // WORKAROUND (NeighborSearch bug, reported): buildFamilies returns EMPTY families when every point
  // has the same z (a 2D model): the zero extent gives a 1e-300 cell size and (z -/+ h)/cell
  // overflows the long cast. A sentinel candidate 2 horizons above the plane gives the z axis a
  // finite extent; it lies outside every horizon, so it is never a neighbour and does not change the
  // families. Test ElasticOsbLattice.BuildFamiliesOnPlanarPoints checks the bug itself.
  std::vector<double> candidates(L.x);
  if (planar) candidates.insert(candidates.end(), {0.0, 0.0, 2.0 * L.horizon + dx});
  pf::buildFamilies(candidates, L.numQueries, std::vector<double>(L.numQueries, L.horizon), L.fam);
  L.fam.numNodes = L.numNodes;  // the sentinel is not a node: x, volume, y and force hold numNodes
  L.fam.influence.resize(L.fam.numBonds());
  for (std::size_t b = 0; b < L.fam.numBonds(); ++b)
    L.fam.influence[b] = pf::influenceValue(infl, L.fam.refLength[b], L.horizon);
  L.m.assign(L.numQueries, 0.0);
  pf::computeWeightedVolume(L.view(), L.m.data());
  return L;
}

// The lattice's positions moved by independent uniform random offsets in [-amplitude, amplitude] per in-plane (2D)
// or every (3D) component; a fixed seed makes the motion repeatable.
inline std::vector<double> randomMotion(const Lattice& L, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  std::vector<double> y = L.x;
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < (L.planar ? 2 : 3); ++a) y[3 * p + a] += u(rng);
  return y;
}

// y = x + a smooth field + a deterministic per-node jitter, so that a correspondence model's hourglass forces are
// not zero (3D; the z part is left out on a planar lattice).
inline std::vector<double> jitteredMotion(const Lattice& L) {
  std::vector<double> y(L.x);
  for (int p = 0; p < L.numNodes; ++p) {
    const double* x = &L.x[3 * p];
    const double jitter = 1e-7 * std::sin(12.9898 * p + 78.233);
    y[3 * p] += 1e-3 * x[0] + 2e-1 * x[1] * x[1] + jitter;
    y[3 * p + 1] += -4e-4 * x[1] + 1e-1 * x[0] * x[1] - jitter;
    if (!L.planar) y[3 * p + 2] += 3e-4 * x[2] + 1e-1 * x[0] * x[2] + 0.5 * jitter;
  }
  return y;
}

inline std::unique_ptr<pf::ElasticMaterial> makeElastic(pf::Dimension dim, double E, double nu,
                                                        double thickness) {
  pf::MaterialInput in;
  in.name = "unit test solid";
  in.inputFile = "test_elastic_osb";
  in.values["Density"] = 7800.0;
  in.values["Young's Modulus"] = E;
  in.values["Poisson's Ratio"] = nu;
  if (dim == pf::Dimension::PlaneStress) in.values["Plane Stress"] = 1.0;
  if (dim == pf::Dimension::PlaneStrain) in.values["Plane Strain"] = 1.0;
  if (dim != pf::Dimension::ThreeD) in.values["Thickness"] = thickness;
  pf::applySpecs(pf::ElasticMaterial::entry().parameters, in);  // the spec defaults the input layer fills
  return std::unique_ptr<pf::ElasticMaterial>(new pf::ElasticMaterial(in));
}

}  // namespace pftest
