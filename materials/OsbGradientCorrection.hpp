#pragma once
// The OSB J2 solid's `Gradient Correction` = `Quadratic` (issue 38; docs/materials.md, "Gradient correction"): a
// point's state (dilatation, deviatoric extension, yield) is read from its bonds with the quadratic part of the
// deformation removed. Per point: the weighted least-squares fit Y_b = A xi_b + Q(xi_b, xi_b) over its family (weights
// omega V_j, the bonds the kernel counts; 9 coefficients per component in 3D, 5 in the plane), and each bond's length
// becomes |Y_b - Q(xi_b, xi_b)| with its direction kept (the change limited smoothly to 5 % of |xi_b|:
// limitedCorrection). A bond's extension is the strain at its midpoint to second order, so a family reads the strain
// at the centroid of its bonds' midpoints: at the point for a symmetric family, inside the body for a surface point's
// one-sided family (a bending field's surface strain read low, the yield delayed). After the correction every point
// reads the affine part at itself. Without enough bonds in general position for the fit (a singular moment matrix) a
// point reads its bonds as they are.
#include <cmath>
#include <cstddef>
#include <vector>

#include "OsbBondLoops.hpp"
#include "core/BondFamily.hpp"

namespace pf {
namespace osb {

// Cholesky factor of the symmetric positive definite N x N matrix M in place (lower triangle, L L^T = M); false when
// M is not positive definite (to round-off).
template <int N>
inline bool choleskyFactor(double M[N][N]) {
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
  return true;
}

// Solves L L^T X = R for column col of R (N x 3) in place, L from choleskyFactor.
template <int N>
inline void choleskySolve(const double L[N][N], double R[N][3], int col) {
  double z[N];
  for (int r = 0; r < N; ++r) {
    double v = R[r][col];
    for (int k = 0; k < r; ++k) v -= L[r][k] * z[k];
    z[r] = v / L[r][r];
  }
  for (int r = N - 1; r >= 0; --r) {
    double v = z[r];
    for (int k = r + 1; k < N; ++k) v -= L[k][r] * R[k][col];
    R[r][col] = v / L[r][r];
  }
}

// The fit's sizes: N coefficients per component, the first kLinear of them linear, the last kQuadratic quadratic.
template <int N>
constexpr int kLinearOf = N == 5 ? 2 : 3;
// Per point, what the tangent keeps of the fit at its Newton point (kept by J2Tangent; sizes for 3D, the plane uses
// the first entries): the quadratic rows of M^-1 (the map from the right-hand side sum w phi a to the quadratic
// coefficients) and the quadratic coefficients of the bond vectors Y.
constexpr int kMaxFitRows = 6 * 9, kMaxFitCoefficients = 6 * 3;

// Per thread, node i's fit basis and weights (fillFitBasis) and, for the node removeQuadratic read last, its corrected
// bond vectors Y' = Y - Q(xi, xi), the uncorrected lengths |Y| and room for the tangent's corrected direction dY'.
// Every array padded to whole chunks past the family with zeros (lengths 1), since the loops read whole lanes.
struct CorrectedBonds {
  // lenQ: |Y'|; slope: the limiter's derivative g' per bond (limitedCorrection)
  std::vector<double> y0, y1, y2, lenY, lenQ, slope, p0, p1, p2;
  std::vector<double> basis, weight;  // basis[r * stride + k]: term r of bond k (xi / delta); weight omega V_j
  std::size_t stride = 0;
};
inline CorrectedBonds& correctedBonds() {
  static thread_local CorrectedBonds c;
  return c;
}

// Fills the basis of node i's bonds, xi scaled by 1/delta, the linear terms first (3D: xi0, xi1, xi2, then
// xi0^2/2, xi1^2/2, xi2^2/2, xi0 xi1, xi0 xi2, xi1 xi2; planar: xi0, xi1, xi0^2/2, xi1^2/2, xi0 xi1), and the weights
// omega V_j (vj: the gathered V_j, 0 for a broken bond). Sizes the arrays of cb for the family.
template <bool Unit, int N>
PF_INLINE void fillFitBasis(const FamilyView& fam, int i, const double* vj, CorrectedBonds& cb) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0, padded = roundUpToLanes(n);
  const std::size_t size = static_cast<std::size_t>(n) + 2 * kLanes;
  if (cb.y0.size() < size)
    for (std::vector<double>* v : {&cb.y0, &cb.y1, &cb.y2, &cb.lenY, &cb.lenQ, &cb.slope, &cb.p0, &cb.p1, &cb.p2})
      v->assign(size, 0.0);
  if (cb.stride < size) cb.stride = size, cb.basis.assign(9 * size, 0.0), cb.weight.assign(size, 0.0);
  const std::size_t st = cb.stride;
  double* phi = cb.basis.data();
  const double s = 1.0 / fam.horizon, xi0 = fam.x[3 * i], xi1 = fam.x[3 * i + 1], xi2 = fam.x[3 * i + 2];
  for (int k = 0; k < padded; ++k) {
    double e0 = 0.0, e1 = 0.0, e2 = 0.0, w = 0.0;
    if (k < n) {
      const int j = fam.neighbors[b0 + k];
      e0 = (fam.x[3 * j] - xi0) * s, e1 = (fam.x[3 * j + 1] - xi1) * s, e2 = (fam.x[3 * j + 2] - xi2) * s;
      w = (Unit ? 1.0 : fam.influence[b0 + k]) * vj[k];
    }
    cb.weight[k] = w;
    if (N == 5) {
      phi[k] = e0, phi[st + k] = e1, phi[2 * st + k] = 0.5 * e0 * e0, phi[3 * st + k] = 0.5 * e1 * e1;
      phi[4 * st + k] = e0 * e1;
      continue;
    }
    phi[k] = e0, phi[st + k] = e1, phi[2 * st + k] = e2;
    phi[3 * st + k] = 0.5 * e0 * e0, phi[4 * st + k] = 0.5 * e1 * e1, phi[5 * st + k] = 0.5 * e2 * e2;
    phi[6 * st + k] = e0 * e1, phi[7 * st + k] = e0 * e2, phi[8 * st + k] = e1 * e2;
  }
}

// sum_k a_k b_k c_k over whole chunks of kLanes (the padding adds zeros), summed per lane.
PF_INLINE double tripleSum(int padded, const double* a, const double* b, const double* c) {
  Lanes acc = {};
  for (int k = 0; k < padded; k += kLanes)
    acc += FullChunk{}.load(a + k) * FullChunk{}.load(b + k) * FullChunk{}.load(c + k);
  return laneSum(acc);
}

// The weighted right-hand side R = sum_k w_k phi_k a_k (N x 3) of the node whose basis cb holds; with M (lower
// triangle) the moment matrix sum w phi phi^T when M is given.
template <int N>
PF_INLINE void fitSums(int n, const CorrectedBonds& cb, const double* a0, const double* a1, const double* a2,
                       double (*M)[N], double R[N][3]) {
  const int padded = roundUpToLanes(n);
  const double *phi = cb.basis.data(), *w = cb.weight.data();
  for (int r = 0; r < N; ++r) {
    const double* pr = phi + r * cb.stride;
    if (M)
      for (int c = 0; c <= r; ++c) M[r][c] = tripleSum(padded, w, pr, phi + c * cb.stride);
    R[r][0] = tripleSum(padded, w, pr, a0), R[r][1] = tripleSum(padded, w, pr, a1);
    R[r][2] = tripleSum(padded, w, pr, a2);
  }
}

// a -= Q(xi, xi) for the bonds of the node whose basis cb holds, Q's coefficients q (kQuadratic x 3, row-major).
template <int N>
PF_INLINE void subtractFitted(int n, const CorrectedBonds& cb, const double* q, double* __restrict a0,
                              double* __restrict a1, double* __restrict a2) {
  constexpr int L = kLinearOf<N>;
  for (int r = L; r < N; ++r) {
    const double* __restrict pr = cb.basis.data() + r * cb.stride;
    const double q0 = q[3 * (r - L)], q1 = q[3 * (r - L) + 1], q2 = q[3 * (r - L) + 2];
    for (int k = 0; k < n; ++k) a0[k] -= pr[k] * q0, a1[k] -= pr[k] * q1, a2[k] -= pr[k] * q2;
  }
}

// Subtracts from the vectors (a0, a1, a2) of node i's bonds their weighted least-squares quadratic part (the basis
// and weights in cb, fillFitBasis); false (nothing changed) when the fit is singular. When q is given it receives the
// quadratic coefficients (kQuadratic x 3), and rows, when given, the quadratic rows of M^-1 (kQuadratic x N): what
// subtractKeptFit needs to apply the same fit to other vectors (the fit is linear in them) without forming M again.
template <int N>
PF_INLINE bool subtractQuadraticOf(int n, const CorrectedBonds& cb, double* a0, double* a1, double* a2,
                                   double* q = nullptr, double* rows = nullptr) {
  constexpr int L = kLinearOf<N>;
  double M[N][N] = {}, R[N][3] = {};
  fitSums<N>(n, cb, a0, a1, a2, M, R);
  if (!choleskyFactor<N>(M)) return false;
  for (int col = 0; col < 3; ++col) choleskySolve<N>(M, R, col);
  double coeff[kMaxFitCoefficients];
  double* c = q ? q : coeff;
  for (int r = L; r < N; ++r)
    for (int col = 0; col < 3; ++col) c[3 * (r - L) + col] = R[r][col];
  if (rows)
    for (int r = L; r < N; ++r) {  // row r of M^-1 = column r (M symmetric): the solve of the unit vector e_r
      double E[N][3] = {};
      E[r][0] = 1.0;
      choleskySolve<N>(M, E, 0);
      for (int col = 0; col < N; ++col) rows[N * (r - L) + col] = E[col][0];
    }
  subtractFitted<N>(n, cb, c, a0, a1, a2);
  return true;
}

// The kept fit applied to other vectors of the bonds of the node whose basis cb holds (the tangent's direction):
// q = rows . sum w phi a, then a -= Q(xi, xi). The same weights as the fit the rows came from (a broken bond has
// V_j = 0 in both).
template <int N>
PF_INLINE void subtractKeptFit(int n, const CorrectedBonds& cb, const double* rows, double* a0, double* a1,
                               double* a2) {
  constexpr int L = kLinearOf<N>;
  double R[N][3] = {}, q[kMaxFitCoefficients];
  fitSums<N>(n, cb, a0, a1, a2, nullptr, R);
  for (int r = 0; r < N - L; ++r)
    for (int col = 0; col < 3; ++col) {
      double v = 0.0;
      for (int k = 0; k < N; ++k) v += rows[N * r + k] * R[k][col];
      q[3 * r + col] = v;
    }
  subtractFitted<N>(n, cb, q, a0, a1, a2);
}

// Y and |Y| of n bonds into the corrected-bond arrays (restrict: so that GCC vectorizes the copy, as dropBrokenBonds).
PF_INLINE void copyBonds(int n, const double* __restrict d0, const double* __restrict d1, const double* __restrict d2,
                         const double* __restrict len, double* __restrict c0, double* __restrict c1,
                         double* __restrict c2, double* __restrict lenY) {
  for (int k = 0; k < n; ++k) c0[k] = d0[k], c1[k] = d1[k], c2[k] = d2[k], lenY[k] = len[k];
}

// The correction of a bond's length, d = |Y| - |Y'|, is a second-order term: for the smooth fields it is made for it
// is a small share of |xi| (a bending field's surface layer, the plate's hole edge: below 1e-2). Where the fit takes
// in a field that is not smooth (a prescribed line of points, a crack tip) it can exceed the bond's whole stretch and
// even reverse it (|Y'| half of |xi| for a bond stretched 25 %, beside the coarse beam's loaded line): the force is
// then no longer monotone in the stretch and Newton stalls. So the correction is limited smoothly to
// kCorrectionLimit |xi|: g(d) = d / sqrt(1 + (d / (c |xi|))^2), which is d to 1e-2 relative below 0.14 c |xi| and at
// most c |xi|; g'(d) = (1 + (d / (c |xi|))^2)^(-3/2).
constexpr double kCorrectionLimit = 0.05;
struct LimitedCorrection {
  double value, slope;
};
PF_INLINE LimitedCorrection limitedCorrection(double d, double xi) {
  const double r = d / (kCorrectionLimit * xi), q = 1.0 / std::sqrt(1.0 + r * r);
  return {d * q, q * q * q};
}

// Each bond's length becomes |Y| - g(|Y| - |Y'|) (c: Y'; limitedCorrection), its vector Y keeps its direction with that
// length; |Y'| and g' kept for the tangent.
PF_INLINE void rescaleToCorrected(int n, const double* __restrict c0, const double* __restrict c1,
                                  const double* __restrict c2, const double* __restrict xr, double* __restrict d0,
                                  double* __restrict d1, double* __restrict d2, double* __restrict len,
                                  double* __restrict lenQ, double* __restrict slope) {
  for (int k = 0; k < n; ++k) {
    const double lq = std::sqrt(c0[k] * c0[k] + c1[k] * c1[k] + c2[k] * c2[k]);
    const LimitedCorrection g = limitedCorrection(len[k] - lq, xr[k]);
    const double l = len[k] - g.value;
    const double scale = len[k] > 0.0 ? l / len[k] : 1.0;
    d0[k] *= scale, d1[k] *= scale, d2[k] *= scale;
    len[k] = l;
    lenQ[k] = lq;
    slope[k] = g.slope;
  }
}

// The force's reading of node i's gathered family: each bond's length becomes |Y| - g(|Y| - |Y - Q(xi, xi)|) (g the
// limiter above; |Y - Q| itself for the small corrections of smooth fields), its vector keeps its direction Y/|Y| with
// that length (the force stays along the deformed bond). keptQ: Q's coefficients from an earlier
// fit of the same Y (the tangent's products; subtractQuadraticOf's q), or null to fit here, writing the coefficients
// to q and the rows of M^-1 to rows when those are given. False where the fit is singular (the bonds read as they are).
template <bool Unit>
PF_INLINE bool removeQuadratic(const FamilyView& fam, int i, bool planar, FamilyScratch& sc,
                               const double* keptQ = nullptr, double* q = nullptr, double* rows = nullptr) {
  const int n = fam.offsets[i + 1] - fam.offsets[i];
  CorrectedBonds& cb = correctedBonds();
  if (planar) fillFitBasis<Unit, 5>(fam, i, sc.vj, cb);
  else fillFitBasis<Unit, 9>(fam, i, sc.vj, cb);
  double *c0 = cb.y0.data(), *c1 = cb.y1.data(), *c2 = cb.y2.data();
  copyBonds(n, sc.d0, sc.d1, sc.d2, sc.len, c0, c1, c2, cb.lenY.data());
  for (std::size_t k = n; k < static_cast<std::size_t>(n) + 2 * kLanes; ++k)
    cb.lenY[k] = cb.lenQ[k] = 1.0, cb.slope[k] = 0.0, c0[k] = c1[k] = c2[k] = 0.0, cb.p0[k] = cb.p1[k] = cb.p2[k] = 0.0;
  if (keptQ) {
    if (planar) subtractFitted<5>(n, cb, keptQ, c0, c1, c2);
    else subtractFitted<9>(n, cb, keptQ, c0, c1, c2);
  } else if (!(planar ? subtractQuadraticOf<5>(n, cb, c0, c1, c2, q, rows)
                      : subtractQuadraticOf<9>(n, cb, c0, c1, c2, q, rows))) {
    return false;
  }
  rescaleToCorrected(n, c0, c1, c2, fam.refLength + fam.offsets[i], sc.d0, sc.d1, sc.d2, sc.len, cb.lenQ.data(),
                     cb.slope.data());
  return true;
}

}  // namespace osb
}  // namespace pf
