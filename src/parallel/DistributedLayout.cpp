#include "DistributedLayout.hpp"

#include <Epetra_BlockMap.h>
#include <Epetra_Export.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <numeric>
#include <stdexcept>

#include "discretization/NeighborSearch.hpp"
#include "discretization/PartialVolume.hpp"
#include "discretization/SpaceFillingCurve.hpp"
#include "parallel/Collective.hpp"
#include "parallel/CommunicatorImpl.hpp"

namespace pf {

// Maps and transfers for 1- and 3-component data, index = ncomp == 3.
// The rank-0 maps (every point on rank 0) are built by the first gatherToRoot only: the Exodus output no
// longer needs them (parallel/ChunkedGather.hpp), so a run without checkpoints never holds them.
struct DistributedLayout::Transfers {
  std::unique_ptr<Epetra_BlockMap> owned[2], overlap[2];
  std::unique_ptr<Epetra_Import> import[2];
  mutable std::unique_ptr<Epetra_BlockMap> root[2];
  mutable std::unique_ptr<Epetra_Import> rootImport[2];
  std::unique_ptr<Epetra_Export> exporter[2];
  // Imports of other widths (a two-phase model's per-node rows), built on first use.
  struct Wide {
    std::unique_ptr<Epetra_BlockMap> owned, overlap;
    std::unique_ptr<Epetra_Import> import;
  };
  mutable std::map<int, Wide> wide;
};

DistributedLayout::~DistributedLayout() = default;

namespace {

// Points of other ranks inside the owned points' bounding box grown by the largest horizon (and half a
// cell diagonal for partial volumes), in Hilbert order.
std::vector<int> ghostCandidates(const std::vector<double>& coords, const std::vector<int>& owner, int me,
                                 const std::vector<int>& owned, const std::vector<double>& horizon,
                                 const std::array<double, 3>* cell, const std::vector<std::uint64_t>& key) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, hmax = 0;
  for (int p : owned) {
    hmax = std::max(hmax, horizon[p]);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], coords[3 * p + d]);
      hi[d] = std::max(hi[d], coords[3 * p + d]);
    }
  }
  std::vector<int> candidates;
  if (!owned.empty()) {
    const double pad = (hmax + (cell ? halfCellDiagonal(*cell) : 0.0)) * (1.0 + 1e-9);
    for (int p = 0; p < static_cast<int>(owner.size()); ++p) {
      if (owner[p] == me) continue;
      bool inside = true;
      for (int d = 0; d < 3 && inside; ++d) inside = coords[3 * p + d] >= lo[d] - pad && coords[3 * p + d] <= hi[d] + pad;
      if (inside) candidates.push_back(p);
    }
  }
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) { return key[a] != key[b] ? key[a] < key[b] : a < b; });
  return candidates;
}

// Each row of family sorted by (key, cloud index) of its neighbours, cloud(local) naming a local index's point;
// refLength and fraction (the per-bond arrays set so far) follow their bonds.
template <class CloudIndex>
void sortRows(BondFamily& family, CloudIndex cloud, const std::vector<std::uint64_t>& key) {
  std::vector<int> order, nb;
  std::vector<double> len, frac;
  const bool partial = !family.fraction.empty();
  for (int i = 0; i < family.numOwned(); ++i) {
    const int b0 = family.offsets[i], b1 = family.offsets[i + 1];
    order.resize(b1 - b0);
    std::iota(order.begin(), order.end(), b0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const int pa = cloud(family.neighbors[a]), pb = cloud(family.neighbors[b]);
      return key[pa] != key[pb] ? key[pa] < key[pb] : pa < pb;
    });
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

DistributedLayout::DistributedLayout(const Communicator& comm, const std::vector<double>& coords,
                                     const std::vector<int>& owner, const std::vector<double>& horizon,
                                     const std::vector<int>& block, const Influence& influence,
                                     const std::array<double, 3>* cell, const std::array<double, 3>* box)
    : comm_(comm) {
  const int me = comm_.rank();
  numGlobal_ = static_cast<int>(owner.size());
  const std::vector<std::uint64_t> key = hilbertKeys(coords);

  std::vector<int> owned;
  for (int p = 0; p < numGlobal_; ++p)
    if (owner[p] == me) owned.push_back(p);
  std::sort(owned.begin(), owned.end(), [&](int a, int b) {
    if (block[a] != block[b]) return block[a] < block[b];
    if (key[a] != key[b]) return key[a] < key[b];
    return a < b;
  });
  numOwned_ = static_cast<int>(owned.size());
  // Ghosts: a box neighbourhood reaches as far as the ball around the box.
  std::vector<double> reach = horizon;
  if (box)
    for (double& r : reach) r = std::max(r, std::sqrt((*box)[0] * (*box)[0] + (*box)[1] * (*box)[1] + (*box)[2] * (*box)[2]));
  const std::vector<int> candidates = ghostCandidates(coords, owner, me, owned, reach, cell, key);

  std::vector<double> pts;
  pts.reserve(3 * (owned.size() + candidates.size()));
  for (int p : owned) pts.insert(pts.end(), &coords[3 * p], &coords[3 * p] + 3);
  for (int p : candidates) pts.insert(pts.end(), &coords[3 * p], &coords[3 * p] + 3);
  std::vector<double> h(numOwned_);
  for (int i = 0; i < numOwned_; ++i) h[i] = horizon[owned[i]];
  buildFamilies(pts, numOwned_, h, family_, cell, box);
  // Rows in a global order (Hilbert key, then cloud index) instead of local index order, where a point's
  // on-rank neighbours precede its ghosts: family sums then run in the same order at every rank count.
  const int nOwned = numOwned_;
  sortRows(family_, [&](int local) { return local < nOwned ? owned[local] : candidates[local - nOwned]; }, key);
  // A user-defined influence function can fail (not finite) at some bonds, so on some ranks only.
  collectively(comm_, [&] { setInfluence(family_, h, influence, cell != nullptr); });

  // Keep only candidates that some bond reaches, in candidate (Hilbert) order.
  std::vector<int> ghostIndex(candidates.size(), -1);
  for (int j : family_.neighbors)
    if (j >= numOwned_) ghostIndex[j - numOwned_] = 0;
  gids_ = owned;
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (ghostIndex[c] == 0) {
      ghostIndex[c] = static_cast<int>(gids_.size());
      gids_.push_back(candidates[c]);
    }
  for (int& j : family_.neighbors)
    if (j >= numOwned_) j = ghostIndex[j - numOwned_];
  family_.numNodes = numOverlap();
  std::set<int> sources;  // the ranks this one receives ghosts from (the messages of an import)
  for (std::size_t g = owned.size(); g < gids_.size(); ++g) sources.insert(owner[gids_[g]]);
  numGhostSources_ = static_cast<int>(sources.size());

  for (int i = 0; i < numOwned_; ++i) {
    const int b = block[owned[i]];
    if (blocks_.empty() || blocks_.back().blockId != b) blocks_.push_back({b, i, i});
    blocks_.back().end = i + 1;
  }
  buildTransfers();
}

void DistributedLayout::buildTransfers() {
  auto t = std::make_unique<Transfers>();
  const Epetra_MpiComm& ecomm = comm_.impl().epetra;
  for (int k = 0; k < 2; ++k) {
    const int ncomp = k == 1 ? 3 : 1;
    t->owned[k].reset(new Epetra_BlockMap(-1, numOwned_, gids_.data(), ncomp, 0, ecomm));
    t->overlap[k].reset(new Epetra_BlockMap(-1, numOverlap(), gids_.data(), ncomp, 0, ecomm));
    t->import[k].reset(new Epetra_Import(*t->overlap[k], *t->owned[k]));
    t->exporter[k].reset(new Epetra_Export(*t->overlap[k], *t->owned[k]));
  }
  transfers_ = std::move(t);
}

void DistributedLayout::importToOverlap(const double* owned, double* overlap, int ncomp) const {
  const Epetra_BlockMap *ownedMap, *overlapMap;
  const Epetra_Import* import;
  if (ncomp == 1 || ncomp == 3) {
    const int k = ncomp == 3 ? 1 : 0;
    ownedMap = transfers_->owned[k].get(), overlapMap = transfers_->overlap[k].get();
    import = transfers_->import[k].get();
  } else {
    Transfers::Wide& w = transfers_->wide[ncomp];
    if (!w.import) {  // every rank asks for the same width at the same call: the construction is collective
      const Epetra_MpiComm& ecomm = comm_.impl().epetra;
      w.owned.reset(new Epetra_BlockMap(-1, numOwned_, gids_.data(), ncomp, 0, ecomm));
      w.overlap.reset(new Epetra_BlockMap(-1, numOverlap(), gids_.data(), ncomp, 0, ecomm));
      w.import.reset(new Epetra_Import(*w.overlap, *w.owned));
    }
    ownedMap = w.owned.get(), overlapMap = w.overlap.get(), import = w.import.get();
  }
  Epetra_Vector src(View, *ownedMap, const_cast<double*>(owned));
  Epetra_Vector dst(View, *overlapMap, overlap);
  if (dst.Import(src, *import, Insert) != 0) throw std::runtime_error("Epetra Import to ghosts failed");
}

void DistributedLayout::exportAdd(const double* overlap, double* owned, int ncomp) const {
  const int k = ncomp == 3 ? 1 : 0;
  Epetra_Vector src(View, *transfers_->overlap[k], const_cast<double*>(overlap));
  Epetra_Vector dst(View, *transfers_->owned[k], owned);
  dst.PutScalar(0.0);
  if (dst.Export(src, *transfers_->exporter[k], Add) != 0) throw std::runtime_error("Epetra Export from ghosts failed");
}

std::vector<double> DistributedLayout::gatherToRoot(const double* owned, int ncomp) const {
  const int k = ncomp == 3 ? 1 : 0;
  if (!transfers_->rootImport[k]) {  // collective, as every gatherToRoot
    std::vector<int> all(comm_.rank() == 0 ? numGlobal_ : 0);
    std::iota(all.begin(), all.end(), 0);
    transfers_->root[k].reset(new Epetra_BlockMap(-1, static_cast<int>(all.size()), all.data(), ncomp, 0,
                                                  comm_.impl().epetra));
    transfers_->rootImport[k].reset(new Epetra_Import(*transfers_->root[k], *transfers_->owned[k]));
  }
  std::vector<double> out(comm_.rank() == 0 ? static_cast<std::size_t>(ncomp) * numGlobal_ : 0);
  Epetra_Vector src(View, *transfers_->owned[k], const_cast<double*>(owned));
  Epetra_Vector dst(View, *transfers_->root[k], out.data());
  if (dst.Import(src, *transfers_->rootImport[k], Insert) != 0)
    throw std::runtime_error("Epetra gather to rank 0 failed");
  return out;
}

}  // namespace pf
