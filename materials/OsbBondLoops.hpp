#pragma once
// Building blocks of the OSB bond loops, shared by the elastic and the J2 kernels so that both do the
// same arithmetic (an elastic J2 point gives exactly the "Elastic" force). Internal to materials/.
//
// A node's family is first gathered into a per-node scratch (bond vectors, deformed lengths, neighbour
// volumes: ~10 kB for a 120-bond family, so it stays in L1) and every later loop of that node runs on
// contiguous arrays: one sqrt per bond and step, loops the compiler vectorizes, no allocation or virtual
// call per bond.
//
// The functions are inline so that each target clone of a kernel (PF_KERNEL_CLONES) compiles them for
// its own vector width. Reductions keep kLanes partial sums whatever that width is, so every clone
// adds in the same order and gives bit-identical results.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/BondDamage.hpp"
#include "core/BondFamily.hpp"

// AVX-512 / AVX2 / baseline copies of a kernel, chosen once at load time from the CPU (GCC ifunc).
// The build itself stays at x86-64-v2; results do not depend on the copy (no FMA contraction:
// -ffp-contract=off on the kernel sources, see CMakeLists.txt).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(PF_NO_KERNEL_CLONES)
#define PF_KERNEL_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define PF_KERNEL_CLONES
#endif

#if defined(__GNUC__)
#define PF_INLINE inline __attribute__((always_inline))
#else
#define PF_INLINE inline
#endif

namespace pf {
namespace osb {

// Partial sums per reduction and bonds per vector step: one AVX-512 vector, two AVX2 or four SSE2
// vectors.
constexpr int kLanes = 8;

// kLanes doubles as one value (GCC vector extension): the compiler maps it onto whatever vector width
// the clone has. Only the AVX-512 clone keeps such values in registers: without a native 64-byte vector
// GCC 12 gives them no register mode, so the AVX2 and baseline clones keep partial sums on the stack and
// the AVX2 build ran 2.6-2.9x slower than the AVX-512 clone (BENCHMARKS.md, session 6).
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));

// |v| per lane by clearing the sign bit (exact, as fabs). A vector `v < 0 ? -v : v` compiles to one
// masked negation on AVX-512 but is taken apart lane by lane, through the stack, on AVX2 and SSE2.
typedef long long LaneBits __attribute__((vector_size(kLanes * sizeof(long long))));
PF_INLINE Lanes absLanes(const Lanes& v) {
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneBits>(v) & (LaneBits{} + 0x7fffffffffffffffLL));
}

// Loads and stores of kLanes bonds starting at p.
struct FullChunk {
  PF_INLINE Lanes load(const double* p, double /*fill*/ = 0.0) const {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  PF_INLINE void store(double* p, const Lanes& v) const { std::memcpy(p, &v, sizeof v); }
};

// The last m < kLanes bonds of a family, loaded as a full vector: the lanes past the family read the
// next bonds of the array (finite values of the next node) or the scratch's padding (len 1, V_j 0,
// y_j - y_i 0), so every term a loop adds for them is multiplied by V_j = 0 or y_j - y_i = 0 and is zero.
// Stores write the m lanes only.
struct PaddedTail {
  int m;
  PF_INLINE Lanes load(const double* p, double /*fill*/ = 0.0) const { return FullChunk{}.load(p); }
  PF_INLINE void store(double* p, const Lanes& v) const {
    for (int l = 0; l < m; ++l) p[l] = v[l];
  }
};

// The same for the last family of a block, where a full load could run past the bond arrays: the
// unused lanes hold fill (chosen so that they add zero to every sum and divide by nothing that is
// zero). Slower (the vector is assembled through memory), so used for that one family only.
struct TailChunk {
  int m;
  PF_INLINE Lanes load(const double* p, double fill = 0.0) const {
    double buf[kLanes];
    for (int l = 0; l < kLanes; ++l) buf[l] = l < m ? p[l] : fill;
    Lanes v;
    std::memcpy(&v, buf, sizeof v);
    return v;
  }
  PF_INLINE void store(double* p, const Lanes& v) const {
    for (int l = 0; l < m; ++l) p[l] = v[l];
  }
};

PF_INLINE int roundUpToLanes(int n) { return (n + kLanes - 1) / kLanes * kLanes; }

// Whether node i's bond arrays may be read as whole chunks (PaddedTail) without leaving the block's
// bonds.
PF_INLINE bool chunksStayInBlock(const FamilyView& fam, int i) {
  return fam.offsets[i] + roundUpToLanes(fam.offsets[i + 1] - fam.offsets[i]) <= fam.offsets[fam.end];
}

// Calls body(k, chunk) for the chunks of kLanes bonds of a family of n bonds; the last one is a
// PaddedTail if inBlock (chunksStayInBlock), else a TailChunk. Bond k + l lands in lane l, so a sum kept
// per lane adds bond k in partial sum k mod kLanes.
template <class Body>
PF_INLINE void forEachChunk(int n, bool inBlock, Body&& body) {
  int k = 0;
  for (; k + kLanes <= n; k += kLanes) body(k, FullChunk{});
  if (k < n) {
    if (inBlock) body(k, PaddedTail{n - k});
    else body(k, TailChunk{n - k});
  }
}

// Adds the kLanes partial sums in a fixed tree.
PF_INLINE double laneSum(const Lanes& acc) {
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

struct FamilyScratch {
  double *d0 = nullptr, *d1 = nullptr, *d2 = nullptr;  // y_j - y_i
  double *len = nullptr;                               // |y_j - y_i|
  double *vj = nullptr;                                // V_j
  double *a = nullptr, *b = nullptr;                   // per-bond work arrays of the caller
  double *g0 = nullptr, *g1 = nullptr, *g2 = nullptr;  // force on the far end, before the scatter
};

// A node's (y, V), or its force (f, 0), as one 32-byte record: the gather then reads a neighbour with
// one vector load and the scatter updates it with one vector read-modify-write. Gather and scatter took
// 33 instructions per bond with per-component scalar accesses, 25 with records (BENCHMARKS.md, session
// 4) and take about 18 with records moved four at a time through register transposes (session 5).
typedef double Quad __attribute__((vector_size(4 * sizeof(double))));

struct NodeRecords {
  const Quad* pos = nullptr;  // (y_j, V_j) of every overlap node of the view
  Quad* force = nullptr;      // (f_j, 0), copied from force and back (so the sums round as on force itself)
};

// Thread-local records for the fam.numNodes overlap nodes: positions packed from y and fam.volume, and,
// if force is not null, the force records loaded from it. Grown, never shrunk. A kernel that throws
// before storeForces leaves force as it was.
NodeRecords nodeRecords(const FamilyView& fam, const double* y, const double* force);

// Writes the force records back to force (3 per node).
void storeForces(const FamilyView& fam, const NodeRecords& rec, double* force);

// Position records (y_j, V_j) of the fam.numNodes overlap nodes in buf (grown, never shrunk; aligned as
// nodeRecords' own): for a caller that keeps positions while nodeRecords holds another vector (the J2 tangent's
// products: positions y and the direction dy).
const Quad* positionRecords(const FamilyView& fam, const double* y, std::vector<double>& buf);

// Thread-local scratch for families of up to the largest family of [fam.begin, fam.end); grown, never
// shrunk (one allocation per thread and size, not per call).
FamilyScratch& familyScratch(const FamilyView& fam);

// Software prefetch of the bond streams of the family kPrefetchAhead nodes after node i. The hardware
// prefetchers leave the first touch of each family's stream (refLength, e^dp) waiting on memory: with
// this the hardening kernel on a 40^3 cube ran 1.38x faster (BENCHMARKS.md, session 4); 1, 2 and 4 nodes
// ahead measured alike, 2 leaves room on a slower memory.
constexpr int kPrefetchAhead = 2;

// Asks for bonds [offsets[i], offsets[i + 1]) of a per-bond array (write: the kernel will store there).
template <class T>
PF_INLINE void prefetchBondRange(const FamilyView& fam, int i, const T* a, bool write) {
  constexpr int kPerLine = 64 / sizeof(T);
  const int b1 = fam.offsets[i + 1];
  for (int b = fam.offsets[i]; b < b1; b += kPerLine) {
    if (write) __builtin_prefetch(a + b, 1, 3);
    else __builtin_prefetch(a + b, 0, 3);
  }
}

// The family's own streams (neighbours, reference lengths, influence and fractions where read) for the
// node kPrefetchAhead after i; a kernel adds its state streams with prefetchBondRange.
PF_INLINE int prefetchFamily(const FamilyView& fam, int i) {
  const int ahead = i + kPrefetchAhead;
  if (ahead >= fam.end) return -1;
  prefetchBondRange(fam, ahead, fam.neighbors, false);
  prefetchBondRange(fam, ahead, fam.refLength, false);
  if (!fam.unitInfluence) prefetchBondRange(fam, ahead, fam.influence, false);
  if (fam.fraction) prefetchBondRange(fam, ahead, fam.fraction, false);
  return ahead;
}

// Software prefetch of the position and force records of the neighbours of node i + 1, a node ahead of
// its gather and scatter. It pays only where the records overflow the per-core L2: the J2 kernel ran 8-9 %
// faster on the 40^3 cube and 2-13 % faster on the 80^3 one (4 and 32 MB of records; the host's noise is
// that wide), the elastic one 5 % at 80^3, but the J2 kernel ran 13 % slower on a 16^3 cube (256 kB of
// records, already in L2), where the prefetch only adds three instructions per bond (BENCHMARKS.md,
// session 6). Hence the size test; 1 MiB is the L2 of the AMD EPYC measured there. positions: a third record array
// read at the same neighbours (the J2 tangent's positions y, beside the direction's records in rec).
constexpr std::size_t kRecordPrefetchBytes = std::size_t(1) << 20;
PF_INLINE bool prefetchRecordsPays(const FamilyView& fam, const NodeRecords& rec) {
  return rec.force && 2 * sizeof(Quad) * static_cast<std::size_t>(fam.numNodes) > kRecordPrefetchBytes;
}
PF_INLINE void prefetchNeighbourRecords(const FamilyView& fam, const NodeRecords& rec, int i,
                                        const Quad* positions = nullptr) {
  const int next = i + 1;
  if (next >= fam.end) return;
  const int* __restrict nb = fam.neighbors;
  const int b1 = fam.offsets[next + 1];
  for (int b = fam.offsets[next]; b < b1; ++b) {
    __builtin_prefetch(rec.pos + nb[b], 0, 3);
    __builtin_prefetch(rec.force + nb[b], 1, 3);
    if (positions) __builtin_prefetch(positions + nb[b], 0, 3);
  }
}

PF_INLINE Quad loadQuad(const double* p) {
  Quad v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
PF_INLINE void storeQuad(double* p, const Quad& v) { std::memcpy(p, &v, sizeof v); }

// Transposes the 4x4 block whose rows are a, b, c, d (8 shuffles): four bonds' records become four
// component vectors, and back. Moves values only, so the results keep their bits.
PF_INLINE void transpose4(Quad& a, Quad& b, Quad& c, Quad& d) {
  const Quad ab0 = __builtin_shufflevector(a, b, 0, 4, 2, 6), ab1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const Quad cd0 = __builtin_shufflevector(c, d, 0, 4, 2, 6), cd1 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  a = __builtin_shufflevector(ab0, cd0, 0, 1, 4, 5);
  b = __builtin_shufflevector(ab1, cd1, 0, 1, 4, 5);
  c = __builtin_shufflevector(ab0, cd0, 2, 3, 6, 7);
  d = __builtin_shufflevector(ab1, cd1, 2, 3, 6, 7);
}

// Bond damage on a gathered family of n bonds: writes each bond's trial flag bt (bondBroken from the committed
// bn, the length len and |xi| xr) and takes a broken bond out of the family (V_j = 0, y_j - y_i = 0); returns
// the number broken. A function of its own so that the restrict parameters let GCC vectorize the loop (with
// the same pointers as locals of gatherFamily it gave up on the alias checks: 60 % more time per bond).
PF_INLINE long dropBrokenBonds(int n, const double* __restrict xr, const double* __restrict bn, double* __restrict bt,
                               double s, const double* __restrict len, double* __restrict vj, double* __restrict d0,
                               double* __restrict d1, double* __restrict d2) {
  long count = 0;  // a 64-bit integer sum of 0/1 doubles: vectorizes (a double sum keeps its order and does not)
  for (int b = 0; b < n; ++b) {
    const double broken = bondBroken(bn[b], len[b], xr[b], s) ? 1.0 : 0.0;
    const double keep = 1.0 - broken;
    bt[b] = broken;
    count += static_cast<long>(broken);
    vj[b] *= keep;
    d0[b] *= keep;
    d1[b] *= keep;
    d2[b] *= keep;
  }
  return count;
}

// How many of n bonds are stretched past s (bondBroken with no committed break): the test of an intact node.
PF_INLINE long countStretched(int n, const double* __restrict xr, const double* __restrict len, double s) {
  long count = 0;
  for (int b = 0; b < n; ++b) count += bondBroken(0.0, len[b], xr[b], s) ? 1 : 0;
  return count;
}

// Gathers node i's family into the scratch; returns its size.
PF_INLINE int gatherFamily(const FamilyView& fam, const Quad* __restrict pos, int i, FamilyScratch& sc) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* __restrict nb = fam.neighbors + b0;
  double* __restrict d0 = sc.d0;
  double* __restrict d1 = sc.d1;
  double* __restrict d2 = sc.d2;
  double* __restrict len = sc.len;
  double* __restrict vj = sc.vj;
  Quad yi = pos[i];
  yi[3] = 0.0;  // so that the fourth lane passes V_j through unchanged
  // Four neighbours at a time: one record load and subtraction each, then a register transpose into
  // the component arrays (4 stores per 4 bonds, where per-bond component stores took 4 per bond; on the
  // AMD EPYC of BENCHMARKS.md, session 4, AVX-512 gathers instead of the record loads ran 11 % slower).
  // The sqrt sits in this loop so that it overlaps the loads and shuffles (a loop of sqrts alone waits on
  // the divider); std::sqrt vectorizes (-fno-math-errno on the kernel sources) and sqrtpd rounds as
  // sqrtsd, so the tail's scalar sqrt gives the same bits.
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    Quad r0 = pos[nb[k]] - yi, r1 = pos[nb[k + 1]] - yi, r2 = pos[nb[k + 2]] - yi, r3 = pos[nb[k + 3]] - yi;
    transpose4(r0, r1, r2, r3);
    storeQuad(d0 + k, r0); storeQuad(d1 + k, r1); storeQuad(d2 + k, r2); storeQuad(vj + k, r3);
    const Quad l2 = r0 * r0 + r1 * r1 + r2 * r2;
    storeQuad(len + k, Quad{std::sqrt(l2[0]), std::sqrt(l2[1]), std::sqrt(l2[2]), std::sqrt(l2[3])});
  }
  for (; k < n; ++k) {
    const Quad r = pos[nb[k]] - yi;
    d0[k] = r[0]; d1[k] = r[1]; d2[k] = r[2];
    vj[k] = r[3];
    len[k] = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  }
  // Partial volumes: the neighbour counts with the share of its cell inside the horizon.
  if (fam.fraction) {
    const double* __restrict fr = fam.fraction + b0;
    for (int b = 0; b < n; ++b) vj[b] *= fr[b];
  }
  // Bond damage: a broken bond leaves the family. V_j = 0 drops it from every family sum (dilatation, yield
  // norms: Peridigm multiplies each of its terms by 1 - bond damage) and y_j - y_i = 0 makes its force and
  // reaction zero; its length stays, so no quotient divides by zero. Only blocks with a damage model pay.
  if (fam.brokenN) {
    // A node with no broken bond committed whose stretches all stay below s_c (nearly all nodes at nearly all
    // steps) reads and writes no flag (BondDamage.hpp, contract); its last trial may need clearing.
    long count = 0;
    const bool intact = fam.brokenCountN[i] == 0.0;
    if (intact) count = countStretched(n, fam.refLength + b0, len, fam.criticalStretch);
    if (count > 0 || !intact)
      count = dropBrokenBonds(n, fam.refLength + b0, fam.brokenN + b0, fam.broken + b0, fam.criticalStretch, len, vj, d0,
                              d1, d2);
    else if (fam.brokenCount[i] != 0.0)
      for (int b = 0; b < n; ++b) fam.broken[b0 + b] = 0.0;
    fam.brokenCount[i] = static_cast<double>(count);
    fam.damage[i] = n > 0 ? static_cast<double>(count) / n : 0.0;  // Peridigm's Damage: the broken share
  }
  // Padding of the last chunk (see PaddedTail).
  for (int b = n; b < roundUpToLanes(n); ++b) {
    d0[b] = d1[b] = d2[b] = 0.0;
    len[b] = 1.0;
    vj[b] = 0.0;
  }
  return n;
}

// dv_j - dv_i of node i's family into e0, e1, e2 from records (dv_j, .) of any per-node vector (a direction dy);
// padded to whole chunks with 0. The same record loads and transposes as gatherFamily, without lengths or damage.
PF_INLINE void gatherDifferences(const FamilyView& fam, const Quad* __restrict pos, int i, double* __restrict e0,
                                 double* __restrict e1, double* __restrict e2) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* __restrict nb = fam.neighbors + b0;
  const Quad vi = pos[i];
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    Quad r0 = pos[nb[k]] - vi, r1 = pos[nb[k + 1]] - vi, r2 = pos[nb[k + 2]] - vi, r3 = pos[nb[k + 3]] - vi;
    transpose4(r0, r1, r2, r3);
    storeQuad(e0 + k, r0); storeQuad(e1 + k, r1); storeQuad(e2 + k, r2);
  }
  for (; k < n; ++k) {
    const Quad r = pos[nb[k]] - vi;
    e0[k] = r[0]; e1[k] = r[1]; e2[k] = r[2];
  }
  for (int b = n; b < roundUpToLanes(n); ++b) e0[b] = e1[b] = e2[b] = 0.0;
}

// omega_k v for the chunk at bond k; Unit (FamilyView::unitInfluence): omega = 1, v itself, without
// reading the array (1 * v == v exactly, so both give the same bits).
template <bool Unit, class Chunk>
PF_INLINE Lanes weighted(const Chunk& c, const double* __restrict w, int k, const Lanes& v) {
  if constexpr (Unit) return v;
  else return c.load(w + k) * v;
}

// sum_k omega_k x_k (len_k - x_k - ep_k) V_k over the family (ep null: no plastic extension); inBlock
// from chunksStayInBlock. Each term is omega x (e - e^dp) V_j (Eqs. 4/16), e = len - x. With xx, the same
// pass also stores sum_k x_k^2 V_k there (the J2 kernel's x.x moment: as a fifth sum of its trial pass it
// spilled that pass's partial sums to the stack in the AVX2 clone, which has 16 vector registers).
template <bool Unit>
PF_INLINE double dilatationSum(const double* __restrict w, const double* __restrict x, const double* __restrict len,
                               const double* __restrict ep, const double* __restrict vj, int n, bool inBlock,
                               double* xx = nullptr) {
  Lanes acc = {}, sxx = {};
  auto sum = [&](auto withEp, auto withXx) {
    forEachChunk(n, inBlock, [&](int k, auto c) {
      const Lanes xk = c.load(x + k), vk = c.load(vj + k);
      if constexpr (decltype(withEp)::value)
        acc += weighted<Unit>(c, w, k, xk) * ((c.load(len + k) - xk) - c.load(ep + k)) * vk;
      else
        acc += weighted<Unit>(c, w, k, xk) * (c.load(len + k) - xk) * vk;
      if constexpr (decltype(withXx)::value) sxx += xk * xk * vk;
    });
  };
  using Yes = std::true_type;
  using No = std::false_type;
  if (xx) {
    if (ep) sum(Yes{}, Yes{});
    else sum(No{}, Yes{});
    *xx = laneSum(sxx);
  } else {
    if (ep) sum(Yes{}, No{});
    else sum(No{}, No{});
  }
  return laneSum(acc);
}

// The scatter of addBondForces: f_j += (g0, g1, g2)_k, times the bond's fraction, for node i's bonds k, then f_i +=
// own. Four bonds at a time, transposed back into records: one read-modify-write per neighbour. Partial volumes:
// the reaction on j carries the same share of the bond as f_i (V_j fr).
PF_INLINE void scatterReactions(const FamilyView& fam, int i, const double* __restrict g0, const double* __restrict g1,
                                const double* __restrict g2, const Quad& own, Quad* __restrict force) {
  const int b0 = fam.offsets[i], n = fam.offsets[i + 1] - b0;
  const int* __restrict nb = fam.neighbors + b0;
  const double* __restrict fr = fam.fraction ? fam.fraction + b0 : nullptr;
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    Quad q0 = loadQuad(g0 + k), q1 = loadQuad(g1 + k), q2 = loadQuad(g2 + k), q3 = {};
    if (fr) {
      const Quad f = loadQuad(fr + k);
      q0 *= f; q1 *= f; q2 *= f;
    }
    transpose4(q0, q1, q2, q3);
    force[nb[k]] += q0; force[nb[k + 1]] += q1; force[nb[k + 2]] += q2; force[nb[k + 3]] += q3;
  }
  for (; k < n; ++k) {
    const double f = fr ? fr[k] : 1.0;  // g * 1 == g exactly
    force[nb[k]] += Quad{g0[k] * f, g1[k] * f, g2[k] * f, 0.0};
  }
  force[i] += own;
}

// f_i += t V_j along each bond, f_j -= t V_i, with forceOverLength(k, chunk) giving s = t / len (the
// scalar force state over the deformed length) for the chunk at bond k; inBlock as for forEachChunk.
// The arithmetic runs on vectors into the scratch; the scatter to the neighbours is one record
// read-modify-write per bond (force: the records of nodeRecords).
template <class ForceOverLength>
PF_INLINE void addBondForces(const FamilyView& fam, int i, const FamilyScratch& sc, bool inBlock,
                             ForceOverLength&& forceOverLength, Quad* __restrict force) {
  const int n = fam.offsets[i + 1] - fam.offsets[i];
  // The reaction -t V_i is stored negated and added (x - y == x + (-y) exactly): an addition can take
  // the record from memory, a subtraction from it cannot.
  const double mVi = -fam.volume[i];
  // Local copies of the scratch pointers: the stores (memcpy) could alias sc itself, which would reload
  // every pointer in every chunk.
  const double* __restrict d0 = sc.d0;
  const double* __restrict d1 = sc.d1;
  const double* __restrict d2 = sc.d2;
  const double* __restrict vjs = sc.vj;
  double* __restrict g0 = sc.g0;
  double* __restrict g1 = sc.g1;
  double* __restrict g2 = sc.g2;
  Lanes a0 = {}, a1 = {}, a2 = {};
  forEachChunk(n, inBlock, [&](int k, auto c) {
    // Padded lanes: y_j - y_i = 0 and len = 1 there, so s is finite and t0..t2 vanish.
    const Lanes sk = forceOverLength(k, c), vj = c.load(vjs + k);
    const Lanes t0 = sk * c.load(d0 + k), t1 = sk * c.load(d1 + k), t2 = sk * c.load(d2 + k);
    a0 += t0 * vj; a1 += t1 * vj; a2 += t2 * vj;
    FullChunk{}.store(g0 + k, t0 * mVi); FullChunk{}.store(g1 + k, t1 * mVi); FullChunk{}.store(g2 + k, t2 * mVi);
  });
  scatterReactions(fam, i, g0, g1, g2, Quad{laneSum(a0), laneSum(a1), laneSum(a2), 0.0}, force);
}

}  // namespace osb
}  // namespace pf
