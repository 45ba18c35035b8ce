#include "PalsInfluence.hpp"

#include <cmath>

namespace pf {
namespace pals {

namespace {

void dilatationModes(const double* z, double* e) {
  const double a = z[0], b = z[1], c = z[2];
  e[0] = a * a; e[1] = b * b; e[2] = c * c;
  e[3] = 2 * (a * b); e[4] = 2 * (a * c); e[5] = 2 * (b * c);
}

void deviatoricModes(const double* z, double* e) {
  const double a = z[0], b = z[1], c = z[2];
  const double a2 = a * a, b2 = b * b, c2 = c * c, ab = a * b, ac = a * c, bc = b * c;
  const double r = std::sqrt(a2 + b2 + c2), avg = r / 3.0;
  e[0] = a2 / r - avg; e[1] = b2 / r - avg; e[2] = c2 / r - avg;
  e[3] = 2 * ab / r; e[4] = 2 * ac / r; e[5] = 2 * bc / r;
}

// LU with partial pivoting of the 6x6 k (row-major, a copy), then the solve for rhs in place (LAPACK's dgetrf/dgetrs,
// which Peridigm calls). False for an exactly zero pivot.
bool solveInPlace(const double* kIn, double* rhs) {
  double k[kModes * kModes];
  for (int p = 0; p < kModes * kModes; ++p) k[p] = kIn[p];
  for (int col = 0; col < kModes; ++col) {
    int piv = col;
    for (int r = col + 1; r < kModes; ++r)
      if (std::fabs(k[r * kModes + col]) > std::fabs(k[piv * kModes + col])) piv = r;
    if (k[piv * kModes + col] == 0.0 || !std::isfinite(k[piv * kModes + col])) return false;
    if (piv != col) {
      for (int c = 0; c < kModes; ++c) std::swap(k[piv * kModes + c], k[col * kModes + c]);
      std::swap(rhs[piv], rhs[col]);
    }
    for (int r = col + 1; r < kModes; ++r) {
      const double f = k[r * kModes + col] / k[col * kModes + col];
      for (int c = col + 1; c < kModes; ++c) k[r * kModes + c] -= f * k[col * kModes + c];
      rhs[r] -= f * rhs[col];
    }
  }
  for (int r = kModes - 1; r >= 0; --r) {
    double s = rhs[r];
    for (int c = r + 1; c < kModes; ++c) s -= k[r * kModes + c] * rhs[c];
    rhs[r] = s / k[r * kModes + r];
  }
  for (int r = 0; r < kModes; ++r)
    if (!std::isfinite(rhs[r])) return false;
  return true;
}

}  // namespace

double omega(const double* z, double omega0, const double* w) {
  const double a = z[0], b = z[1], c = z[2];
  return omega0 + (w[0] * a * a + w[1] * b * b + w[2] * c * c + 2.0 * (w[3] * a * b + w[4] * a * c + w[5] * b * c));
}

double sigma(const double* z, double sigma0, const double* w) {
  double e[kModes];
  deviatoricModes(z, e);
  return sigma0 + (w[0] * e[0] * e[0] + w[1] * e[1] * e[1] + w[2] * e[2] * e[2] + w[3] * e[3] * e[3] +
                   w[4] * e[4] * e[4] + w[5] * e[5] * e[5]);
}

MultiplierSystem::MultiplierSystem() {
  for (int p = 0; p < kModes * kModes; ++p) kDil_[p] = kDev_[p] = 0.0;
  for (int i = 0; i < kModes; ++i) rhsDil_[i] = rhsDev_[i] = 0.0;
}

void MultiplierSystem::add(const double* z, double v, double omega0, double sigma0) {
  double e[kModes], d[kModes];
  dilatationModes(z, e);
  deviatoricModes(z, d);
  for (int i = 0; i < kModes; ++i)
    for (int j = 0; j < kModes; ++j) {
      kDil_[i * kModes + j] += e[i] * e[j] * v;
      kDev_[i * kModes + j] += (d[i] * d[i]) * (d[j] * d[j]) * v;
    }
  for (int i = 0; i < kModes; ++i) {
    rhsDil_[i] += omega0 * e[i] * v;
    rhsDev_[i] += sigma0 * d[i] * d[i] * v;
  }
}

bool MultiplierSystem::solve(Multipliers& out) const {
  static const double kDilTarget[kModes] = {1, 1, 1, 0, 0, 0};
  static const double kDevTarget[kModes] = {2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 2, 2, 2};
  double kDil[kModes * kModes], kDev[kModes * kModes];
  for (int p = 0; p < kModes * kModes; ++p) kDil[p] = kDil_[p], kDev[p] = kDev_[p];
  double* lam = out.dilatation;
  double* tau = out.deviatoric;
  for (int i = 0; i < kModes; ++i) lam[i] = kDilTarget[i] - rhsDil_[i], tau[i] = kDevTarget[i] - rhsDev_[i];
  // A mode the family does not span (its diagonal a vanishing share of the trace: e.g. z = 0 for every bond of a
  // planar mesh) is decoupled: its row and column 0, diagonal 1, right-hand side 0 (Peridigm's fix, pals.cxx).
  double trace = 0.0;
  for (int i = 0; i < kModes; ++i) trace += kDil[i * kModes + i];
  for (int i = 0; i < kModes; ++i) {
    if (!(kDil[i * kModes + i] / trace < 1.0e-15)) continue;
    for (int j = 0; j < kModes; ++j)
      kDil[i * kModes + j] = kDil[j * kModes + i] = kDev[i * kModes + j] = kDev[j * kModes + i] = 0.0;
    kDil[i * kModes + i] = kDev[i * kModes + i] = 1.0;
    lam[i] = tau[i] = 0.0;
  }
  return solveInPlace(kDil, lam) && solveInPlace(kDev, tau);
}

}  // namespace pals
}  // namespace pf
