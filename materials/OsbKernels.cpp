#include "OsbKernels.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace pf {

namespace osb {

FamilyScratch& familyScratch(const FamilyView& fam) {
  thread_local std::vector<double> buf;
  thread_local FamilyScratch s;
  int nmax = 0;
  for (int i = fam.begin; i < fam.end; ++i) nmax = std::max(nmax, fam.offsets[i + 1] - fam.offsets[i]);
  const std::size_t n = static_cast<std::size_t>(nmax);
  if (buf.size() < 7 * n || !s.d0) {
    buf.assign(7 * n, 0.0);
    double* p = buf.data();
    s.d0 = p; s.d1 = p + n; s.d2 = p + 2 * n; s.len = p + 3 * n; s.vj = p + 4 * n; s.a = p + 5 * n; s.b = p + 6 * n;
  }
  return s;
}

int gatherFamily(const FamilyView& fam, const double* __restrict y, int i, FamilyScratch& sc) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* __restrict nb = fam.neighbors + b0;
  const double* __restrict V = fam.volume;
  double* __restrict d0 = sc.d0;
  double* __restrict d1 = sc.d1;
  double* __restrict d2 = sc.d2;
  double* __restrict len = sc.len;
  double* __restrict vj = sc.vj;
  const double yi0 = y[3 * i], yi1 = y[3 * i + 1], yi2 = y[3 * i + 2];
  for (int k = 0; k < n; ++k) {
    const int j = nb[k];
    d0[k] = y[3 * j] - yi0; d1[k] = y[3 * j + 1] - yi1; d2[k] = y[3 * j + 2] - yi2;
    vj[k] = V[j];
  }
  int k = 0;
#ifdef __SSE2__
  // Two lengths at a time: sqrtpd rounds exactly as sqrtsd (std::sqrt alone does not vectorize: errno).
  for (; k + 2 <= n; k += 2) {
    const __m128d a = _mm_loadu_pd(d0 + k), b = _mm_loadu_pd(d1 + k), c = _mm_loadu_pd(d2 + k);
    const __m128d sq = _mm_add_pd(_mm_add_pd(_mm_mul_pd(a, a), _mm_mul_pd(b, b)), _mm_mul_pd(c, c));
    _mm_storeu_pd(len + k, _mm_sqrt_pd(sq));
  }
#endif
  for (; k < n; ++k) len[k] = std::sqrt(d0[k] * d0[k] + d1[k] * d1[k] + d2[k] * d2[k]);
  return n;
}

double dilatationSum(const double* __restrict w, const double* __restrict x, const double* __restrict len,
                     const double* __restrict ep, const double* __restrict vj, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int k = 0;
  if (ep) {
    for (; k + 4 <= n; k += 4) {
      s0 += w[k] * x[k] * ((len[k] - x[k]) - ep[k]) * vj[k];
      s1 += w[k + 1] * x[k + 1] * ((len[k + 1] - x[k + 1]) - ep[k + 1]) * vj[k + 1];
      s2 += w[k + 2] * x[k + 2] * ((len[k + 2] - x[k + 2]) - ep[k + 2]) * vj[k + 2];
      s3 += w[k + 3] * x[k + 3] * ((len[k + 3] - x[k + 3]) - ep[k + 3]) * vj[k + 3];
    }
    for (; k < n; ++k) s0 += w[k] * x[k] * ((len[k] - x[k]) - ep[k]) * vj[k];
  } else {
    for (; k + 4 <= n; k += 4) {
      s0 += w[k] * x[k] * (len[k] - x[k]) * vj[k];
      s1 += w[k + 1] * x[k + 1] * (len[k + 1] - x[k + 1]) * vj[k + 1];
      s2 += w[k + 2] * x[k + 2] * (len[k + 2] - x[k + 2]) * vj[k + 2];
      s3 += w[k + 3] * x[k + 3] * (len[k + 3] - x[k + 3]) * vj[k + 3];
    }
    for (; k < n; ++k) s0 += w[k] * x[k] * (len[k] - x[k]) * vj[k];
  }
  return (s0 + s1) + (s2 + s3);
}

void addBondForces(const FamilyView& fam, int i, const FamilyScratch& sc, const double* __restrict s,
                   double* __restrict force) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* __restrict nb = fam.neighbors + b0;
  const double* __restrict d0 = sc.d0;
  const double* __restrict d1 = sc.d1;
  const double* __restrict d2 = sc.d2;
  const double* __restrict vj = sc.vj;
  const double Vi = fam.volume[i];
  // f_i: two interleaved partial sums per component; f_j: scattered as they come.
  double a0 = 0, a1 = 0, a2 = 0, c0 = 0, c1 = 0, c2 = 0;
  int k = 0;
  for (; k + 2 <= n; k += 2) {
    const double g0 = s[k] * d0[k], g1 = s[k] * d1[k], g2 = s[k] * d2[k];
    const double h0 = s[k + 1] * d0[k + 1], h1 = s[k + 1] * d1[k + 1], h2 = s[k + 1] * d2[k + 1];
    a0 += g0 * vj[k]; a1 += g1 * vj[k]; a2 += g2 * vj[k];
    c0 += h0 * vj[k + 1]; c1 += h1 * vj[k + 1]; c2 += h2 * vj[k + 1];
    double* fj = force + 3 * nb[k];
    fj[0] -= g0 * Vi; fj[1] -= g1 * Vi; fj[2] -= g2 * Vi;
    double* fk = force + 3 * nb[k + 1];
    fk[0] -= h0 * Vi; fk[1] -= h1 * Vi; fk[2] -= h2 * Vi;
  }
  for (; k < n; ++k) {
    const double g0 = s[k] * d0[k], g1 = s[k] * d1[k], g2 = s[k] * d2[k];
    a0 += g0 * vj[k]; a1 += g1 * vj[k]; a2 += g2 * vj[k];
    double* fj = force + 3 * nb[k];
    fj[0] -= g0 * Vi; fj[1] -= g1 * Vi; fj[2] -= g2 * Vi;
  }
  force[3 * i] += a0 + c0; force[3 * i + 1] += a1 + c1; force[3 * i + 2] += a2 + c2;
}

}  // namespace osb

void osbDilatation(const FamilyView& fam, const OsbConstants& c, const double* y, const double* edp,
                   double* theta) {
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = osb::gatherFamily(fam, y, i, sc);
    const double sum = osb::dilatationSum(fam.influence + b0, fam.refLength + b0, sc.len, edp ? edp + b0 : nullptr,
                                          sc.vj, n);
    theta[i] = c.k * c.D * sum / fam.weightedVolume[i];
  }
}

void osbElasticForce(const FamilyView& fam, const OsbConstants& c, const double* y, const double* theta,
                     double* force) {
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  for (int i = fam.begin; i < fam.end; ++i) {
    const int b0 = fam.offsets[i], n = osb::gatherFamily(fam, y, i, sc);
    const double* __restrict xr = fam.refLength + b0;
    const double* __restrict w = fam.influence + b0;
    const double* __restrict len = sc.len;
    double* __restrict s = sc.a;
    const double invm = 1.0 / fam.weightedVolume[i];
    const double iso = (c.A - c.B * c.c) * theta[i] * invm;  // coefficient of omega x
    const double dev = c.B * invm;                          // coefficient of omega e
    // t = omega (iso x + dev e) along the deformed bond: s = t / |y_j - y_i| (vectorizes: divpd)
    for (int k = 0; k < n; ++k) s[k] = w[k] * (iso * xr[k] + dev * (len[k] - xr[k])) / len[k];
    osb::addBondForces(fam, i, sc, s, force);
  }
}

void osbElasticForceDerivative(const FamilyView& fam, const OsbConstants& c, const double* y, const double* dy,
                               double* dforce) {
  const double* V = fam.volume;
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  for (int i = fam.begin; i < fam.end; ++i) {
    const int nb = osb::gatherFamily(fam, y, i, sc);
    const int off = fam.offsets[i];
    const int* nbr = fam.neighbors + off;
    const double* x = fam.refLength + off;
    const double* w = fam.influence + off;
    const double invm = 1.0 / fam.weightedVolume[i];
    // theta and its derivative first: t depends on the whole family through them. sc.a = de = M . dY.
    double theta = 0.0, dtheta = 0.0;
    for (int k = 0; k < nb; ++k) {
      const int j = nbr[k];
      const double dd0 = dy[3 * j] - dy[3 * i], dd1 = dy[3 * j + 1] - dy[3 * i + 1], dd2 = dy[3 * j + 2] - dy[3 * i + 2];
      sc.a[k] = (sc.d0[k] * dd0 + sc.d1[k] * dd1 + sc.d2[k] * dd2) / sc.len[k];
      const double wx = w[k] * x[k] * sc.vj[k];
      theta += wx * (sc.len[k] - x[k]);
      dtheta += wx * sc.a[k];
    }
    theta *= c.k * c.D * invm;
    dtheta *= c.k * c.D * invm;
    const double iso = (c.A - c.B * c.c) * invm, dev = c.B * invm;
    for (int k = 0; k < nb; ++k) {
      const int j = nbr[k];
      const double dd[3] = {dy[3 * j] - dy[3 * i], dy[3 * j + 1] - dy[3 * i + 1], dy[3 * j + 2] - dy[3 * i + 2]};
      const double len = sc.len[k], de = sc.a[k];
      const double M[3] = {sc.d0[k] / len, sc.d1[k] / len, sc.d2[k] / len};
      const double t = w[k] * (iso * theta * x[k] + dev * (len - x[k]));
      const double dt = w[k] * (iso * dtheta * x[k] + dev * de);
      // d(t M) = dt M + t (I - M M^T) dY / |Y|
      for (int e = 0; e < 3; ++e) {
        const double dT = dt * M[e] + t * (dd[e] - M[e] * de) / len;
        dforce[3 * i + e] += dT * sc.vj[k];
        dforce[3 * j + e] -= dT * V[i];
      }
    }
  }
}

void osbPairStiffness(const FamilyView& fam, const OsbConstants& c, double* stiffness) {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double scale = c.B / fam.weightedVolume[i];
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) stiffness[b] = scale * fam.influence[b];
  }
}

void osbStiffnessBound(const FamilyView& fam, const OsbConstants& c, double* bound) {
  const double coupling = std::fabs(c.A - c.B * c.c) * c.k * c.D;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double m = fam.weightedVolume[i];
    double S = 0.0;  // sum omega x V: scale of d theta / d e
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      S += fam.influence[b] * fam.refLength[b] * fam.volume[fam.neighbors[b]];
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = fam.influence[b], x = fam.refLength[b], Vj = fam.volume[j];
      // A bond along n couples component a to all three: sum_b |n_a n_b| = |n_a| |n|_1 <= max_a of it.
      double n[3], n1 = 0.0, nmax = 0.0;
      for (int d = 0; d < 3; ++d) {
        n[d] = std::fabs(fam.x[3 * j + d] - fam.x[3 * i + d]) / x;
        n1 += n[d];
        nmax = std::max(nmax, n[d]);
      }
      // t_ij (through m_i) and t_ji (through m_j) both load node i; the dilatation coupling of t_ji runs
      // over j's family, bounded here by i's sum S with the smaller of the two weighted volumes.
      const double mj = fam.weightedVolume[j], mmin = std::min(m, mj);
      sum += Vj * w * nmax * n1 * (c.B / m + c.B / mj + 2.0 * coupling * x * S / (m * mmin));
    }
    bound[i] = 2.0 * sum;
  }
}

}  // namespace pf
