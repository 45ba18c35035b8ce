#pragma once
// The OSB J2 solid's `Gradient Correction` = `Quadratic` (issue 38; docs/materials.md, "Gradient correction"): a
// point's state (dilatation, deviatoric extension, yield) is read from its bonds with the quadratic part of the
// deformation removed. Per point: the weighted least-squares fit Y_b = A xi_b + Q(xi_b, xi_b) over its family (weights
// omega V_j, the bonds the kernel counts; 9 coefficients per component in 3D, 5 in the plane), and each bond's length
// becomes |Y_b - Q(xi_b, xi_b)| with its direction kept. A bond's extension is the strain at its midpoint to second
// order, so a family reads the strain at the centroid of its bonds' midpoints: at the point for a symmetric family,
// inside the body for a surface point's one-sided family (a bending field's surface strain read low, the yield
// delayed). After the correction every point reads the affine part at itself. Without enough bonds in general
// position for the fit (a singular moment matrix) a point reads its bonds as they are.
#include <cmath>
#include <cstddef>
#include <vector>

#include "OsbBondLoops.hpp"
#include "core/BondFamily.hpp"

namespace pf {
namespace osb {

// Solves the symmetric positive definite N x N system M X = R (3 right-hand sides) in place by Cholesky; false when M
// is not positive definite (to round-off).
template <int N>
inline bool solveSpd(double M[N][N], double R[N][3]) {
  for (int c = 0; c < N; ++c) {
    double d = M[c][c];
    for (int k = 0; k < c; ++k) d -= M[c][k] * M[c][k];
    if (!(d > 1e-12 * M[c][c])) return false;  // singular to round-off (or a zero row)
    M[c][c] = std::sqrt(d);
    for (int r = c + 1; r < N; ++r) {
      double v = M[r][c];
      for (int k = 0; k < c; ++k) v -= M[r][k] * M[c][k];
      M[r][c] = v / M[c][c];
    }
  }
  for (int col = 0; col < 3; ++col) {
    double z[N];
    for (int r = 0; r < N; ++r) {
      double v = R[r][col];
      for (int k = 0; k < r; ++k) v -= M[r][k] * z[k];
      z[r] = v / M[r][r];
    }
    for (int r = N - 1; r >= 0; --r) {
      double v = z[r];
      for (int k = r + 1; k < N; ++k) v -= M[k][r] * R[k][col];
      R[r][col] = v / M[r][r];
    }
  }
  return true;
}

// The fit's basis for bond k of node i, xi scaled by 1/delta: the linear terms first (3D: xi0, xi1, xi2, then
// xi0^2/2, xi1^2/2, xi2^2/2, xi0 xi1, xi0 xi2, xi1 xi2; planar: xi0, xi1, xi0^2/2, xi1^2/2, xi0 xi1).
template <int N>
inline void quadraticBasis(const FamilyView& fam, int i, int k, double* phi) {
  const int j = fam.neighbors[fam.offsets[i] + k];
  const double s = 1.0 / fam.horizon;
  const double e0 = (fam.x[3 * j] - fam.x[3 * i]) * s, e1 = (fam.x[3 * j + 1] - fam.x[3 * i + 1]) * s;
  if (N == 5) {
    phi[0] = e0, phi[1] = e1, phi[2] = 0.5 * e0 * e0, phi[3] = 0.5 * e1 * e1, phi[4] = e0 * e1;
    return;
  }
  const double e2 = (fam.x[3 * j + 2] - fam.x[3 * i + 2]) * s;
  phi[0] = e0, phi[1] = e1, phi[2] = e2;
  phi[3] = 0.5 * e0 * e0, phi[4] = 0.5 * e1 * e1, phi[5] = 0.5 * e2 * e2;
  phi[6] = e0 * e1, phi[7] = e0 * e2, phi[8] = e1 * e2;
}

// Subtracts from the vectors (a0, a1, a2) of node i's bonds their weighted least-squares quadratic part (weights
// omega vj); false (nothing changed) when the fit is singular. Linear in the vectors: the tangent applies it to the
// direction's bond differences.
template <bool Unit, int N>
inline bool subtractQuadraticOf(const FamilyView& fam, int i, const double* vj, double* a0, double* a1, double* a2) {
  constexpr int kLinear = N == 5 ? 2 : 3;
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  double M[N][N] = {}, R[N][3] = {};
  for (int k = 0; k < n; ++k) {
    const double w = (Unit ? 1.0 : fam.influence[b0 + k]) * vj[k];
    if (w == 0.0) continue;
    double phi[N];
    quadraticBasis<N>(fam, i, k, phi);
    for (int r = 0; r < N; ++r) {
      for (int c = 0; c <= r; ++c) M[r][c] += w * phi[r] * phi[c];
      R[r][0] += w * phi[r] * a0[k], R[r][1] += w * phi[r] * a1[k], R[r][2] += w * phi[r] * a2[k];
    }
  }
  for (int r = 0; r < N; ++r)
    for (int c = r + 1; c < N; ++c) M[r][c] = M[c][r];
  if (!solveSpd<N>(M, R)) return false;
  for (int k = 0; k < n; ++k) {
    double phi[N];
    quadraticBasis<N>(fam, i, k, phi);
    for (int q = kLinear; q < N; ++q) a0[k] -= phi[q] * R[q][0], a1[k] -= phi[q] * R[q][1], a2[k] -= phi[q] * R[q][2];
  }
  return true;
}

template <bool Unit>
inline bool subtractQuadratic(const FamilyView& fam, int i, bool planar, const double* vj, double* a0, double* a1,
                              double* a2) {
  return planar ? subtractQuadraticOf<Unit, 5>(fam, i, vj, a0, a1, a2)
                : subtractQuadraticOf<Unit, 9>(fam, i, vj, a0, a1, a2);
}

// Per thread, for the node removeQuadratic read last: its corrected bond vectors Y' = Y - Q(xi, xi), the uncorrected
// lengths |Y|, and room for the tangent's corrected direction dY'. Padded past the family as the scratch is (length 1,
// vectors 0), since the chunked loops read whole lanes.
struct CorrectedBonds {
  std::vector<double> y0, y1, y2, lenY, p0, p1, p2;
};
inline CorrectedBonds& correctedBonds() {
  static thread_local CorrectedBonds c;
  return c;
}

// The force's reading of node i's gathered family: each bond's length becomes |Y - Q(xi, xi)|, its vector keeps its
// direction Y/|Y| with that length (the force stays along the deformed bond).
template <bool Unit>
inline void removeQuadratic(const FamilyView& fam, int i, bool planar, FamilyScratch& sc) {
  const int n = fam.offsets[i + 1] - fam.offsets[i];
  CorrectedBonds& cb = correctedBonds();
  const std::size_t size = static_cast<std::size_t>(n) + 2 * kLanes;
  if (cb.y0.size() < size)
    for (std::vector<double>* v : {&cb.y0, &cb.y1, &cb.y2, &cb.lenY, &cb.p0, &cb.p1, &cb.p2}) v->assign(size, 0.0);
  double *c0 = cb.y0.data(), *c1 = cb.y1.data(), *c2 = cb.y2.data();
  for (int k = 0; k < n; ++k) c0[k] = sc.d0[k], c1[k] = sc.d1[k], c2[k] = sc.d2[k], cb.lenY[k] = sc.len[k];
  for (std::size_t k = n; k < size; ++k)
    cb.lenY[k] = 1.0, c0[k] = c1[k] = c2[k] = 0.0, cb.p0[k] = cb.p1[k] = cb.p2[k] = 0.0;
  if (!subtractQuadratic<Unit>(fam, i, planar, sc.vj, c0, c1, c2)) return;
  for (int k = 0; k < n; ++k) {
    const double l = std::sqrt(c0[k] * c0[k] + c1[k] * c1[k] + c2[k] * c2[k]);
    const double scale = sc.len[k] > 0.0 ? l / sc.len[k] : 1.0;
    sc.d0[k] *= scale, sc.d1[k] *= scale, sc.d2[k] *= scale;
    sc.len[k] = l;
  }
}

}  // namespace osb
}  // namespace pf
