#include "OsbKernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "OsbBondLoops.hpp"

namespace pf {

namespace osb {

FamilyScratch& familyScratch(const FamilyView& fam) {
  constexpr std::size_t kArrays = 10;
  thread_local std::vector<double> buf;
  thread_local FamilyScratch s;
  int nmax = 0;
  for (int i = fam.begin; i < fam.end; ++i) nmax = std::max(nmax, fam.offsets[i + 1] - fam.offsets[i]);
  // Each array starts on a 64-byte line (a multiple of 8 doubles apart, buffer aligned below).
  const std::size_t n = (static_cast<std::size_t>(nmax) + 7) / 8 * 8;
  if (buf.size() < kArrays * n + 8 || !s.d0) {
    buf.assign(kArrays * n + 8, 0.0);
    double* p = buf.data();
    while (reinterpret_cast<std::uintptr_t>(p) % 64 != 0) ++p;
    double** arrays[kArrays] = {&s.d0, &s.d1, &s.d2, &s.len, &s.vj, &s.a, &s.b, &s.g0, &s.g1, &s.g2};
    for (std::size_t k = 0; k < kArrays; ++k) *arrays[k] = p + k * n;
  }
  return s;
}

namespace {
// n records in a thread-local buffer aligned to a 64-byte line (std::vector<Quad> does not guarantee the
// 32-byte alignment of Quad: large blocks come from mmap at a 16-byte offset).
Quad* recordBuffer(std::vector<double>& buf, std::size_t n) {
  if (buf.size() < 4 * n + 8) buf.assign(4 * n + 8, 0.0);
  double* p = buf.data();
  while (reinterpret_cast<std::uintptr_t>(p) % 64 != 0) ++p;
  return reinterpret_cast<Quad*>(p);
}
}  // namespace

const Quad* positionRecords(const FamilyView& fam, const double* y, std::vector<double>& buf) {
  // Every family and owned node must lie inside the records (a view not made by makeView may lack it).
  if (fam.numNodes < fam.end) throw std::logic_error("node records: FamilyView::numNodes is not set");
  const std::size_t n = static_cast<std::size_t>(fam.numNodes);
  Quad* pos = recordBuffer(buf, n);
  const double* V = fam.volume;
  for (std::size_t j = 0; j < n; ++j) pos[j] = Quad{y[3 * j], y[3 * j + 1], y[3 * j + 2], V[j]};
  return pos;
}

NodeRecords nodeRecords(const FamilyView& fam, const double* y, const double* force) {
  thread_local std::vector<double> posBuf, forceBuf;
  NodeRecords r;
  r.pos = positionRecords(fam, y, posBuf);
  const std::size_t n = static_cast<std::size_t>(fam.numNodes);
  if (force) {
    Quad* frc = recordBuffer(forceBuf, n);
    for (std::size_t j = 0; j < n; ++j) frc[j] = Quad{force[3 * j], force[3 * j + 1], force[3 * j + 2], 0.0};
    r.force = frc;
  }
  return r;
}

void storeForces(const FamilyView& fam, const NodeRecords& rec, double* force) {
  for (int j = 0; j < fam.numNodes; ++j)
    for (int c = 0; c < 3; ++c) force[3 * j + c] = rec.force[j][c];
}

}  // namespace osb

namespace {

// theta_i = k (D/m_i) sum_j omega x (e - e^dp) V_j (Eqs. 4/16), from a gathered family; Unit: omega = 1.
template <bool Unit>
PF_INLINE double nodeDilatation(const FamilyView& fam, const OsbConstants& c, int i, const osb::FamilyScratch& sc,
                                const double* ep, int n) {
  const int b0 = fam.offsets[i];
  const double sum =
      osb::dilatationSum<Unit>(fam.influence + b0, fam.refLength + b0, sc.len, ep, sc.vj, n, osb::chunksStayInBlock(fam, i));
  // A point without bonds (m = 0) has no dilatation: 0, as Peridigm writes, not 0/0.
  return n > 0 ? c.k * c.D * sum / fam.weightedVolume[i] : 0.0;
}

// Adds node i's elastic bond forces (Eqs. 7-13) from its gathered family and its dilatation.
template <bool Unit>
PF_INLINE void addNodeElasticForce(const FamilyView& fam, const OsbConstants& c, int i, const osb::FamilyScratch& sc,
                                   double theta, int n, osb::Quad* force) {
  const int b0 = fam.offsets[i];
  const double* __restrict xr = fam.refLength + b0;
  const double* __restrict w = fam.influence + b0;
  const double* __restrict len = sc.len;
  const double invm = 1.0 / fam.weightedVolume[i];
  const double iso = (c.A - c.B * c.c) * theta * invm;  // coefficient of omega x
  const double dev = c.B * invm;                        // coefficient of omega e
  // t = omega (iso x + dev e) along the deformed bond: s = t / |y_j - y_i|
  auto forceOverLength = [&](int k, auto ch) {
    const osb::Lanes x = ch.load(xr + k), l = ch.load(len + k, 1.0);
    return osb::weighted<Unit>(ch, w, k, iso * x + dev * (l - x)) / l;
  };
  osb::addBondForces(fam, i, sc, osb::chunksStayInBlock(fam, i), forceOverLength, force);
}

template <bool Unit>
PF_INLINE void elasticDilatationAndForce(const FamilyView& fam, const OsbConstants& c, const osb::NodeRecords& rec,
                                         osb::FamilyScratch& sc, double* theta) {
  const bool prefetchRecords = osb::prefetchRecordsPays(fam, rec);
  for (int i = fam.begin; i < fam.end; ++i) {
    osb::prefetchFamily(fam, i);
    if (prefetchRecords) osb::prefetchNeighbourRecords(fam, rec, i);
    const int n = osb::gatherFamily(fam, rec.pos, i, sc);
    theta[i] = nodeDilatation<Unit>(fam, c, i, sc, nullptr, n);
    addNodeElasticForce<Unit>(fam, c, i, sc, theta[i], n, rec.force);
  }
}

}  // namespace

PF_KERNEL_CLONES void osbDilatation(const FamilyView& fam, const OsbConstants& c, const double* y, const double* edp,
                                    double* theta) {
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, nullptr);
  for (int i = fam.begin; i < fam.end; ++i) {
    const int ahead = osb::prefetchFamily(fam, i);
    if (edp && ahead >= 0) osb::prefetchBondRange(fam, ahead, edp, false);
    const int n = osb::gatherFamily(fam, rec.pos, i, sc);
    const double* ep = edp ? edp + fam.offsets[i] : nullptr;
    theta[i] = fam.unitInfluence ? nodeDilatation<true>(fam, c, i, sc, ep, n) : nodeDilatation<false>(fam, c, i, sc, ep, n);
  }
}

PF_KERNEL_CLONES void osbElasticForce(const FamilyView& fam, const OsbConstants& c, const double* y,
                                      const double* theta, double* force) {
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, force);
  for (int i = fam.begin; i < fam.end; ++i) {
    osb::prefetchFamily(fam, i);
    const int n = osb::gatherFamily(fam, rec.pos, i, sc);
    if (fam.unitInfluence) addNodeElasticForce<true>(fam, c, i, sc, theta[i], n, rec.force);
    else addNodeElasticForce<false>(fam, c, i, sc, theta[i], n, rec.force);
  }
  osb::storeForces(fam, rec, force);
}

PF_KERNEL_CLONES void osbElasticDilatationAndForce(const FamilyView& fam, const OsbConstants& c, const double* y,
                                                   double* theta, double* force) {
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, force);
  // One loop per influence kind, so that the omega = 1 one reads no influence array.
  if (fam.unitInfluence) elasticDilatationAndForce<true>(fam, c, rec, sc, theta);
  else elasticDilatationAndForce<false>(fam, c, rec, sc, theta);
  osb::storeForces(fam, rec, force);
}

void osbElasticEnergy(const FamilyView& fam, const ElasticModuli& em, const double* y, const double* theta,
                      double* energy, const double* edp, const double* scf, double thermal, const double* dT) {
  const double kappa = em.bulk, alpha = 15.0 * em.shear;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double* yi = y + 3 * i;
    const double strain = dT ? thermal * dT[i] : 0.0;  // the free thermal stretch of node i's bonds
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      if (fam.brokenN && fam.broken[b] != 0.0) continue;  // as set by the force evaluation just before
      const int j = fam.neighbors[b];
      const double d0 = y[3 * j] - yi[0], d1 = y[3 * j + 1] - yi[1], d2 = y[3 * j + 2] - yi[2];
      const double xi = fam.refLength[b];
      const double ed =
          std::sqrt(d0 * d0 + d1 * d1 + d2 * d2) - xi - strain * xi - theta[i] * xi / 3.0 - (edp ? edp[b] : 0.0);
      const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
      sum += fam.influence[b] * ed * ed * vj;
    }
    const double m = fam.weightedVolume[i];  // 0 for a point without bonds, whose sum is 0 too
    const double W = 0.5 * kappa * theta[i] * theta[i] + (m > 0.0 ? 0.5 * alpha / m * sum * (scf ? scf[i] : 1.0) : 0.0);
    energy[i] = W * fam.volume[i];
  }
}

void osbElasticForceDerivative(const FamilyView& fam, const OsbConstants& c, const double* y, const double* dy,
                               double* dforce, double thermal, const double* dT) {
  const double* V = fam.volume;
  osb::FamilyScratch& sc = osb::familyScratch(fam);
  const osb::NodeRecords rec = osb::nodeRecords(fam, y, nullptr);
  for (int i = fam.begin; i < fam.end; ++i) {
    const int nb = osb::gatherFamily(fam, rec.pos, i, sc);
    const int off = fam.offsets[i];
    const int* nbr = fam.neighbors + off;
    const double* x = fam.refLength + off;
    const double* w = fam.influence + off;
    const double invm = 1.0 / fam.weightedVolume[i];
    // The free thermal stretch of node i's bonds (osbThermoelasticDilatationAndForce): it shifts the extension, and
    // with it theta and t, but not their derivatives.
    const double strain = dT ? thermal * dT[i] : 0.0;
    // theta and its derivative first: t depends on the whole family through them. sc.a = de = M . dY.
    double theta = 0.0, dtheta = 0.0;
    for (int k = 0; k < nb; ++k) {
      const int j = nbr[k];
      const double dd0 = dy[3 * j] - dy[3 * i], dd1 = dy[3 * j + 1] - dy[3 * i + 1], dd2 = dy[3 * j + 2] - dy[3 * i + 2];
      sc.a[k] = (sc.d0[k] * dd0 + sc.d1[k] * dd1 + sc.d2[k] * dd2) / sc.len[k];
      const double wx = w[k] * x[k] * sc.vj[k];
      theta += wx * (sc.len[k] - x[k] - strain * x[k]);
      dtheta += wx * sc.a[k];
    }
    theta *= c.k * c.D * invm;
    dtheta *= c.k * c.D * invm;
    const double iso = (c.A - c.B * c.c) * invm, dev = c.B * invm;
    for (int k = 0; k < nb; ++k) {
      if (fam.brokenN && fam.broken[off + k] != 0.0) continue;  // no force, no derivative (gatherFamily)
      const int j = nbr[k];
      const double dd[3] = {dy[3 * j] - dy[3 * i], dy[3 * j + 1] - dy[3 * i + 1], dy[3 * j + 2] - dy[3 * i + 2]};
      const double len = sc.len[k], de = sc.a[k];
      const double M[3] = {sc.d0[k] / len, sc.d1[k] / len, sc.d2[k] / len};
      const double t = w[k] * (iso * theta * x[k] + dev * (len - x[k] - strain * x[k]));
      const double dt = w[k] * (iso * dtheta * x[k] + dev * de);
      // d(t M) = dt M + t (I - M M^T) dY / |Y|
      const double Vi = fam.fraction ? V[i] * fam.fraction[off + k] : V[i];  // as addBondForces
      for (int e = 0; e < 3; ++e) {
        const double dT = dt * M[e] + t * (dd[e] - M[e] * de) / len;
        dforce[3 * i + e] += dT * sc.vj[k];
        dforce[3 * j + e] -= dT * Vi;
      }
    }
  }
}

void osbPairStiffness(const FamilyView& fam, const OsbConstants& c, double* stiffness) {
  for (int i = fam.begin; i < fam.end; ++i) {
    const double scale = c.B / fam.weightedVolume[i];
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      stiffness[b] = scale * (fam.fraction ? fam.influence[b] * fam.fraction[b] : fam.influence[b]);
  }
}

void osbStiffnessBound(const FamilyView& fam, const OsbConstants& c, double* bound) {
  const double coupling = std::fabs(c.A - c.B * c.c) * c.k * c.D;
  for (int i = fam.begin; i < fam.end; ++i) {
    const double m = fam.weightedVolume[i];
    double S = 0.0;  // sum omega x V: scale of d theta / d e
    // Partial volumes weight omega here as they weight V_j in the kernels.
    auto weight = [&](int b) { return fam.fraction ? fam.influence[b] * fam.fraction[b] : fam.influence[b]; };
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      S += weight(b) * fam.refLength[b] * fam.volume[fam.neighbors[b]];
    double sum = 0.0;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const int j = fam.neighbors[b];
      const double w = weight(b), x = fam.refLength[b], Vj = fam.volume[j];
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
