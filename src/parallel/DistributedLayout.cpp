#include "DistributedLayout.hpp"


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <numeric>
#include <stdexcept>

#include "discretization/BondCutter.hpp"
#include "discretization/NeighborSearch.hpp"
#include "discretization/PartialVolume.hpp"
#include "discretization/SpaceFillingCurve.hpp"
#include "parallel/Collective.hpp"
#include "parallel/GhostTransfers.hpp"
#include "parallel/PointExchange.hpp"

namespace pf {

DistributedLayout::~DistributedLayout() = default;

namespace {

// The ghost candidates of every rank: the owned points within each rank's box grown by its largest reach (and
// half a cell diagonal for partial volumes). Returns the points received (from: their owners).
PointCloud ghostCandidates(const Communicator& comm, const PointCloud& owned, const std::vector<double>& reach,
                           const std::array<double, 3>* cell, std::vector<int>* from) {
  double rmax = 0;
  for (int i = 0; i < owned.size(); ++i) rmax = std::max(rmax, reach[i]);
  return exchangeNearBoxes(comm, owned, (rmax + (cell ? halfCellDiagonal(*cell) : 0.0)) * (1.0 + 1e-9), from);
}

// The bounding box of the whole cloud (every rank's points), for keys that do not depend on the partition.
std::array<double, 6> globalBox(const Communicator& comm, const PointCloud& owned) {
  double local[6] = {-1e300, -1e300, -1e300, -1e300, -1e300, -1e300}, global[6];  // -lo, hi
  for (int i = 0; i < owned.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      local[d] = std::max(local[d], -owned.x[3 * i + d]);
      local[3 + d] = std::max(local[3 + d], owned.x[3 * i + d]);
    }
  comm.max(local, global, 6);
  return {-global[0], -global[1], -global[2], global[3], global[4], global[5]};
}

// Each row of family sorted by (Hilbert key, cloud index) of its neighbours, order(local) giving that pair
// for a local index; refLength and fraction (the per-bond arrays set so far) follow their bonds.
template <class SortKey>
void sortRows(BondFamily& family, SortKey sortKey) {
  std::vector<int> order, nb;
  std::vector<double> len, frac;
  const bool partial = !family.fraction.empty();
  for (int i = 0; i < family.numOwned(); ++i) {
    const int b0 = family.offsets[i], b1 = family.offsets[i + 1];
    order.resize(b1 - b0);
    std::iota(order.begin(), order.end(), b0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return sortKey(family.neighbors[a]) < sortKey(family.neighbors[b]); });
    nb.clear(), len.clear(), frac.clear();
    for (int b : order) {
      nb.push_back(family.neighbors[b]);
      len.push_back(family.refLength[b]);
      if (partial) frac.push_back(family.fraction[b]);
    }
    std::copy(nb.begin(), nb.end(), family.neighbors.begin() + b0);
    std::copy(len.begin(), len.end(), family.refLength.begin() + b0);
    if (partial) std::copy(frac.begin(), frac.end(), family.fraction.begin() + b0);
  }
}

// omega of every bond from its length and its owner's horizon h. Partial-volume bonds may reach half a
// cell beyond the horizon; omega is taken at the horizon there (omega(r > delta) is undefined for some
// influence functions).
void setInfluence(BondFamily& family, const std::vector<double>& h, const Influence& influence, bool partialVolume) {
  family.influence.resize(family.numBonds());
  for (int i = 0; i < family.numOwned(); ++i)
    for (int b = family.offsets[i]; b < family.offsets[i + 1]; ++b)
      family.influence[b] =
          influenceValue(influence, partialVolume ? std::min(family.refLength[b], h[i]) : family.refLength[b], h[i]);
  family.unitInfluence = std::all_of(family.influence.begin(), family.influence.end(), [](double w) { return w == 1.0; });
}

}  // namespace

namespace {

// Peridigm's "Omit Bonds Between Blocks" = "All": drops every bond whose ends lie in different blocks. Overlap
// index k is owned point owned[k] below owned.size(), else candidate candidates[k - owned.size()].
void keepBondsWithinBlocks(BondFamily& family, const PointCloud& ownedPoints, const std::vector<int>& owned,
                           const PointCloud& ghosts, const std::vector<int>& candidates) {
  const int n = static_cast<int>(owned.size());
  auto blockOf = [&](int k) { return k < n ? ownedPoints.block[owned[k]] : ghosts.block[candidates[k - n]]; };
  keepBonds(family, [&](int i, int j) { return blockOf(i) == blockOf(j); });
}

// Peridigm's Bond Filters. A rank holds both ends of every bond of its owned points (owned points and ghost
// candidates in pts), so the filters need nothing from other ranks.
void removeFilteredBonds(BondFamily& family, const std::vector<double>& pts, const BondFilters& filters) {
  if (filters.empty()) return;
  double longest = 0.0;
  for (double l : family.refLength) longest = std::max(longest, l);
  if (longest > 0.0) removeCutBonds(family, pts, filters, longest);
}

}  // namespace

DistributedLayout::DistributedLayout(const Communicator& comm, const PointCloud& ownedPoints,
                                     const std::vector<double>& horizon, const Influence& influence,
                                     const BondRules& rules)
    : comm_(comm) {
  const std::array<double, 3>* cell = rules.cell;
  const std::array<double, 3>* box = rules.box;
  numGlobal_ = static_cast<int>(ownedPoints.numGlobal);
  numOwned_ = ownedPoints.size();
  // Ghosts: a box neighbourhood reaches as far as the ball around the box.
  std::vector<double> reach = horizon;
  if (box)
    for (double& r : reach) r = std::max(r, std::sqrt((*box)[0] * (*box)[0] + (*box)[1] * (*box)[1] + (*box)[2] * (*box)[2]));
  std::vector<int> from;
  const PointCloud ghosts = ghostCandidates(comm_, ownedPoints, reach, cell, &from);

  const std::array<double, 6> whole = globalBox(comm_, ownedPoints);
  const std::vector<std::uint64_t> ownedKey = hilbertKeys(ownedPoints.x, whole.data(), whole.data() + 3);
  const std::vector<std::uint64_t> ghostKey = hilbertKeys(ghosts.x, whole.data(), whole.data() + 3);
  // Owned points by block, then along the curve; candidates along the curve (gid breaks ties).
  std::vector<int> owned(numOwned_), candidates(ghosts.size());
  std::iota(owned.begin(), owned.end(), 0);
  std::iota(candidates.begin(), candidates.end(), 0);
  std::sort(owned.begin(), owned.end(), [&](int a, int b) {
    if (ownedPoints.block[a] != ownedPoints.block[b]) return ownedPoints.block[a] < ownedPoints.block[b];
    if (ownedKey[a] != ownedKey[b]) return ownedKey[a] < ownedKey[b];
    return ownedPoints.gid[a] < ownedPoints.gid[b];
  });
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) {
    return ghostKey[a] != ghostKey[b] ? ghostKey[a] < ghostKey[b] : ghosts.gid[a] < ghosts.gid[b];
  });

  std::vector<double> pts;
  pts.reserve(3 * (owned.size() + candidates.size()));
  for (int p : owned) pts.insert(pts.end(), &ownedPoints.x[3 * p], &ownedPoints.x[3 * p] + 3);
  for (int c : candidates) pts.insert(pts.end(), &ghosts.x[3 * c], &ghosts.x[3 * c] + 3);
  std::vector<double> h(numOwned_);
  for (int i = 0; i < numOwned_; ++i) h[i] = horizon[owned[i]];
  buildFamilies(pts, numOwned_, h, family_, cell, box);
  if (rules.omitBondsBetweenBlocks) keepBondsWithinBlocks(family_, ownedPoints, owned, ghosts, candidates);
  if (rules.filters) removeFilteredBonds(family_, pts, *rules.filters);
  // Rows in a global order (Hilbert key, then cloud index) instead of local index order, where a point's
  // on-rank neighbours precede its ghosts: family sums then run in the same order at every rank count.
  const int nOwned = numOwned_;
  sortRows(family_, [&](int local) {
    if (local < nOwned) return std::make_pair(ownedKey[owned[local]], ownedPoints.gid[owned[local]]);
    const int c = candidates[local - nOwned];
    return std::make_pair(ghostKey[c], ghosts.gid[c]);
  });
  // A user-defined influence function can fail (not finite) at some bonds, so on some ranks only.
  collectively(comm_, [&] { setInfluence(family_, h, influence, cell != nullptr); });

  // Keep only candidates that some bond reaches, in candidate (Hilbert) order.
  std::vector<int> ghostIndex(candidates.size(), -1);
  for (int j : family_.neighbors)
    if (j >= numOwned_) ghostIndex[j - numOwned_] = 0;
  std::set<int> sources;  // the ranks this one receives ghosts from (the messages of an import)
  for (int p : owned) {
    gids_.push_back(ownedPoints.gid[p]);
    x_.insert(x_.end(), &ownedPoints.x[3 * p], &ownedPoints.x[3 * p] + 3);
    volume_.push_back(ownedPoints.volume[p]);
  }
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (ghostIndex[k] == 0) {
      const int c = candidates[k];
      ghostIndex[k] = static_cast<int>(gids_.size());
      gids_.push_back(ghosts.gid[c]);
      x_.insert(x_.end(), &ghosts.x[3 * c], &ghosts.x[3 * c] + 3);
      volume_.push_back(ghosts.volume[c]);
      sources.insert(from[c]);
    }
  for (int& j : family_.neighbors)
    if (j >= numOwned_) j = ghostIndex[j - numOwned_];
  family_.numNodes = numOverlap();
  numGhostSources_ = static_cast<int>(sources.size());

  for (int i = 0; i < numOwned_; ++i) {
    const int b = ownedPoints.block[owned[i]];
    if (blocks_.empty() || blocks_.back().blockId != b) blocks_.push_back({b, i, i});
    blocks_.back().end = i + 1;
  }
  buildTransfers();
}

void DistributedLayout::buildTransfers() { transfers_ = makeGhostTransfers(comm_, numOwned_, gids_, numGlobal_); }

void DistributedLayout::importToOverlap(const double* owned, double* overlap, int ncomp) const {
  transfers_->importToOverlap(owned, overlap, ncomp);
}

void DistributedLayout::exportAdd(const double* overlap, double* owned, int ncomp) const {
  transfers_->exportAdd(overlap, owned, ncomp);
}

std::vector<double> DistributedLayout::gatherToRoot(const double* owned, int ncomp) const {
  return transfers_->gatherToRoot(owned, ncomp);
}

}  // namespace pf
