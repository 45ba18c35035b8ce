#pragma once
// Position-aware dilatation influence (material parameter `Surface Correction` = `Position Aware` of the OSB
// solids; docs/materials.md, "Surface correction"). Rewrites omega of each bond of rows [begin, end) as
//   omega~ = omega exp(xi.L_i xi / |xi|^2) > 0,  L_i symmetric, per point,
// so that the point's second moment sum omega~ xi (x) xi V' is isotropic (c I) with c = m_i / D: the OSB
// dilatation (D/m) sum omega~ x e V' is then tr(eps) for any small affine strain at every point, a
// truncated family included (the dilatation condition of Mitchell, Silling & Littlewood 2015's Pals, met
// with positive weights). m_i = sum omega~ |xi|^2 V' is unchanged (the trace of the condition). A row no
// positive weights make isotropic (a convex corner or edge) and a symmetric one (the lattice interior) keep
// omega bit for bit.
#include "core/BondFamily.hpp"

namespace pf {

struct PositionAwareSummary {
  int corrected = 0;       // rows whose L was solved (not the rows already isotropic to round-off)
  int singular = 0;        // rows left as they were (too few bonds in general position)
  double minRatio = 1.0;   // smallest omega~ / omega over the rows
  double maxRatio = 1.0;   // largest
};

// x: reference coordinates (3 per overlap node), volume: overlap volumes; planar: the family lies in z = 0
// and only the in-plane moment is made isotropic (D = 2). Sets family.unitInfluence from the result.
PositionAwareSummary positionAwareInfluence(BondFamily& family, int begin, int end, const double* x,
                                            const double* volume, bool planar);

}  // namespace pf
