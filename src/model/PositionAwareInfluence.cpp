#include "PositionAwareInfluence.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

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

// Newton with backtracking on max|R| from L (in place) until max|R| <= tol; false if it stalls (no positive
// weights make the moment isotropic: Newton then walks off towards infinite L) or a step cannot be solved.
template <class Residual>
bool newton(const Residual& residual, double* lambda, int n, double tol) {
  double r[kMax], jac[kMax][kMax];
  double norm = residual(lambda, r, jac);
  for (int it = 0; it < 60; ++it) {
    if (norm <= tol) return true;
    double step[kMax];
    for (int p = 0; p < n; ++p) step[p] = -r[p];
    if (!solve(jac, step, n)) return false;
    double t = 1.0, trial[kMax], rt[kMax], nt = 0.0;
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      for (int p = 0; p < n; ++p) trial[p] = lambda[p] + t * step[p];
      nt = residual(trial, rt, nullptr);
      if (nt < norm) break;
    }
    if (!(nt < norm)) return false;
    for (int p = 0; p < n; ++p) lambda[p] = trial[p];
    norm = residual(lambda, r, jac);
  }
  return norm <= tol;
}

}  // namespace

PositionAwareSummary positionAwareInfluence(BondFamily& family, int begin, int end, const double* x,
                                            const double* volume, bool planar) {
  PositionAwareSummary out;
  const int diag = planar ? 2 : 3;
  std::vector<double> q, e, w;  // per bond of the row: moments, modes, base weight omega V'
  for (int i = begin; i < end; ++i) {
    const int b0 = family.offsets[i], b1 = family.offsets[i + 1], nb = b1 - b0;
    int n = planar ? 3 : 6;
    q.assign(static_cast<std::size_t>(nb) * kMax, 0.0), e.assign(q.size(), 0.0), w.assign(nb, 0.0);
    double trace = 0.0, z[3];
    for (int k = 0; k < nb; ++k) {
      const int b = b0 + k, j = family.neighbors[b];
      for (int d = 0; d < 3; ++d) z[d] = x[3 * j + d] - x[3 * i + d];
      w[k] = family.influence[b] * volume[j] * (family.fraction.empty() ? 1.0 : family.fraction[b]);
      n = moments(z, planar, &q[kMax * k], &e[kMax * k]);
      for (int p = 0; p < diag; ++p) trace += w[k] * q[kMax * k + p];
    }
    // omega~ = omega exp(xi.L xi / |xi|^2) > 0: Newton on the moment residual R(L) = sum w g xi (x) xi - (m/D) I,
    // g = exp(sum L_k e_k). R is the gradient of a convex function of L (its Jacobian sum w g q_p e_k is a Gram
    // matrix up to column scaling), so Newton with backtracking on |R| converges whenever the family spans every
    // direction. The first step from L = 0 is the quadratic (linearised) correction.
    double lambda[kMax] = {};
    auto residual = [&](const double* L, double* r, double jac[kMax][kMax]) {
      double norm = 0.0;
      for (int p = 0; p < n; ++p) {
        r[p] = p < diag ? -trace / diag : 0.0;
        if (jac)
          for (int c = 0; c < n; ++c) jac[p][c] = 0.0;
      }
      for (int k = 0; k < nb; ++k) {
        double s = 0.0;
        for (int p = 0; p < n; ++p) s += L[p] * e[kMax * k + p];
        const double g = w[k] * std::exp(s);
        for (int p = 0; p < n; ++p) {
          r[p] += g * q[kMax * k + p];
          if (jac)
            for (int c = 0; c < n; ++c) jac[p][c] += g * q[kMax * k + p] * e[kMax * k + c];
        }
      }
      for (int p = 0; p < n; ++p) norm = std::max(norm, std::fabs(r[p]));
      return norm;
    };
    // Already isotropic to round-off (a symmetric family: the interior of a lattice): omega stays as it is, bit
    // for bit, rather than take a factor 1 +- 1e-16.
    double r[kMax];
    if (nb == 0 || residual(lambda, r, nullptr) <= 1e-14 * trace) continue;
    if (!newton(residual, lambda, n, 1e-13 * trace)) {
      ++out.singular;
      continue;
    }
    ++out.corrected;
    for (int k = 0; k < nb; ++k) {
      double s = 0.0;
      for (int p = 0; p < n; ++p) s += lambda[p] * e[kMax * k + p];
      const double ratio = std::exp(s);
      out.minRatio = std::min(out.minRatio, ratio);
      out.maxRatio = std::max(out.maxRatio, ratio);
      family.influence[b0 + k] *= ratio;
    }
  }
  family.unitInfluence =
      std::all_of(family.influence.begin(), family.influence.end(), [](double v) { return v == 1.0; });
  return out;
}

}  // namespace pf
