#pragma once
// The geometry of Li & Geng's surface-effect band (seed 003, Section 3.2, Fig. 2-3): the outer layer of a
// lattice body, its outward normals with the paper's corner rules, and the points within 2 delta of it,
// where the NDO divergence form replaces the correspondence force. Built once on the reference cloud.
#include <vector>

#include "core/BondFamily.hpp"
#include "parallel/DistributedLayout.hpp"

namespace pf {

struct SurfaceBand {
  std::vector<double> band;            // per overlap node: 1 within 2 delta of the outer layer, else 0
  std::vector<double> outerNormal;     // 3 per owned node (0 off the outer layer)
  std::vector<double> layerThickness;  // per owned node: its lattice spacing
};

// Outer layer: a point of a lattice (spacing h = its shortest bond) lacks the neighbour at x +- h e_a
// along some axis a (x and y only when planar); n is the sum of those outward directions, so a convex
// corner gets e.g. (-1, 1) and a concave corner, whose four axis neighbours exist, none (the paper's Fig. 3).
// Writes the owned nodes [fam.begin, fam.end).
void outerLayerNormals(const FamilyView& fam, bool planar, double* normal, double* layerThickness);

// flagOut_i = 1 if flag (per overlap node) is set at i or at any neighbour of i, for owned [fam.begin, fam.end):
// one horizon further from the flagged points.
void spreadOneHorizon(const FamilyView& fam, const double* flag, double* flagOut);

// Collective: the band of the whole body from its families (every owned node's block view in views,
// planar per view). Three ghost imports: the outer layer, one horizon, two horizons.
SurfaceBand buildSurfaceBand(const DistributedLayout& layout, const std::vector<FamilyView>& views,
                             const std::vector<bool>& planar);

}  // namespace pf
