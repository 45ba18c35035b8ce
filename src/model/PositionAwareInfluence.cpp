#include "PositionAwareInfluence.hpp"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {

constexpr int kMax = 6;

// Gaussian elimination with partial pivoting of the n x n system k (row-major, kMax wide); rhs in place.
// False for a vanishing pivot (relative to the matrix's largest diagonal).
bool solve(double k[kMax][kMax], double* rhs, int n) {
  double scale = 0.0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, std::fabs(k[i][i]));
  for (int col = 0; col < n; ++col) {
    int piv = col;
    for (int r = col + 1; r < n; ++r)
      if (std::fabs(k[r][col]) > std::fabs(k[piv][col])) piv = r;
    if (!(std::fabs(k[piv][col]) > 1e-12 * scale)) return false;
    if (piv != col) {
      for (int c = 0; c < n; ++c) std::swap(k[piv][c], k[col][c]);
      std::swap(rhs[piv], rhs[col]);
    }
    for (int r = col + 1; r < n; ++r) {
      const double f = k[r][col] / k[col][col];
      for (int c = col; c < n; ++c) k[r][c] -= f * k[col][c];
      rhs[r] -= f * rhs[col];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = rhs[r];
    for (int c = r + 1; c < n; ++c) s -= k[r][c] * rhs[c];
    rhs[r] = s / k[r][r];
  }
  return true;
}

// Products xi_p xi_q of the moment's components (aa, bb, cc, ab, ac, bc; planar: aa, bb, ab) and the modes
// e_k = the same with the off-diagonal ones doubled, over |xi|^2 (xi.L xi / |xi|^2 = sum_k L_k e_k).
int moments(const double* z, bool planar, double* q, double* e) {
  const double a = z[0], b = z[1], c = z[2], r2 = a * a + b * b + c * c;
  if (planar) {
    q[0] = a * a, q[1] = b * b, q[2] = a * b;
    e[0] = q[0] / r2, e[1] = q[1] / r2, e[2] = 2.0 * q[2] / r2;
    return 3;
  }
  q[0] = a * a, q[1] = b * b, q[2] = c * c, q[3] = a * b, q[4] = a * c, q[5] = b * c;
  for (int k = 0; k < 6; ++k) e[k] = (k < 3 ? 1.0 : 2.0) * q[k] / r2;
  return 6;
}

}  // namespace

PositionAwareSummary positionAwareInfluence(BondFamily& family, int begin, int end, const double* x,
                                            const double* volume, bool planar) {
  PositionAwareSummary out;
  const int diag = planar ? 2 : 3;
  for (int i = begin; i < end; ++i) {
    const int b0 = family.offsets[i], b1 = family.offsets[i + 1];
    double k[kMax][kMax] = {}, m2[kMax] = {}, q[kMax], e[kMax], z[3];
    int n = planar ? 3 : 6;
    for (int b = b0; b < b1; ++b) {
      const int j = family.neighbors[b];
      for (int d = 0; d < 3; ++d) z[d] = x[3 * j + d] - x[3 * i + d];
      const double w = family.influence[b] * volume[j] * (family.fraction.empty() ? 1.0 : family.fraction[b]);
      n = moments(z, planar, q, e);
      for (int p = 0; p < n; ++p) {
        m2[p] += w * q[p];
        for (int c = 0; c < n; ++c) k[p][c] += w * q[p] * e[c];
      }
    }
    // Target c I with c = tr(m2) / D, so the trace row asks sum w xi.L xi = 0: m is kept.
    double trace = 0.0;
    for (int p = 0; p < diag; ++p) trace += m2[p];
    double lambda[kMax];
    for (int p = 0; p < n; ++p) lambda[p] = (p < diag ? trace / diag : 0.0) - m2[p];
    // Already isotropic to round-off (a symmetric family: the interior of a lattice): omega stays as it is, bit
    // for bit, rather than take a factor 1 +- 1e-16.
    double offset = 0.0;
    for (int p = 0; p < n; ++p) offset = std::max(offset, std::fabs(lambda[p]));
    if (offset <= 1e-14 * trace) continue;
    if (b1 == b0 || !solve(k, lambda, n)) {
      ++out.singular;
      continue;
    }
    ++out.corrected;
    for (int b = b0; b < b1; ++b) {
      const int j = family.neighbors[b];
      for (int d = 0; d < 3; ++d) z[d] = x[3 * j + d] - x[3 * i + d];
      moments(z, planar, q, e);
      double s = 0.0;
      for (int p = 0; p < n; ++p) s += lambda[p] * e[p];
      const double ratio = 1.0 + s;
      out.minRatio = std::min(out.minRatio, ratio);
      out.maxRatio = std::max(out.maxRatio, ratio);
      family.influence[b] *= ratio;
    }
  }
  family.unitInfluence =
      std::all_of(family.influence.begin(), family.influence.end(), [](double w) { return w == 1.0; });
  return out;
}

}  // namespace pf
