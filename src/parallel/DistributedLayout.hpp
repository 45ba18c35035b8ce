#pragma once
// The points' distribution over ranks: owned and overlap (owned + ghost) points, copying owned values to
// ghosts and adding ghost contributions back (parallel/GhostTransfers, on Tpetra). Owned
// points are ordered by block, then along a Hilbert curve, so a family sits close in memory; bonds of
// the owned points are built here once, on reference positions, in overlap-local indices.
#include <array>
#include <memory>
#include <vector>

#include "core/BondFamily.hpp"
#include "core/BondFilter.hpp"
#include "core/InfluenceFunction.hpp"
#include "discretization/Discretization.hpp"
#include "parallel/ChunkedGather.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/GhostTransfers.hpp"

namespace pf {

struct BlockRange {
  int blockId;      // 1-based block id of the cloud
  int begin, end;   // owned-local node range
};

// How the bonds are made beside the horizon ball. cell: the grid's cell for partial-volume families (see
// buildFamilies), or null for whole neighbour volumes. box: Peridigm's PdQuickGrid box neighbourhood
// (buildFamilies), or null for the spherical one. omitBondsBetweenBlocks: Peridigm's "Omit Bonds Between
// Blocks" = "All", no bond joins points of two blocks. filters: Peridigm's "Bond Filters", no bond crosses one
// (discretization/BondCutter.hpp), or null.
struct BondRules {
  const std::array<double, 3>* cell = nullptr;
  const std::array<double, 3>* box = nullptr;
  bool omitBondsBetweenBlocks = false;
  const BondFilters* filters = nullptr;
};

class DistributedLayout {
 public:
  // Collective. owned: this rank's points (ascending gid, as exchangePoints returns them; numGlobal set),
  // horizon: one per owned point. Ghosts come from the ranks whose points lie within a reach of this rank's
  // bounding box (an exchange of boxes, then of those points): no rank sees the whole cloud. The influence
  // function sets each bond's omega from its length and its owner's horizon; rules: see BondRules.
  DistributedLayout(const Communicator& comm, const PointCloud& owned, const std::vector<double>& horizon,
                    const Influence& influence, const BondRules& rules = {});
  ~DistributedLayout();
  DistributedLayout(const DistributedLayout&) = delete;
  DistributedLayout& operator=(const DistributedLayout&) = delete;

  int numOwned() const { return numOwned_; }
  int numOverlap() const { return static_cast<int>(gids_.size()); }
  int numGlobal() const { return numGlobal_; }
  int numGhosts() const { return numOverlap() - numOwned_; }
  int numGhostSources() const { return numGhostSources_; }  // ranks owning this rank's ghosts
  const std::vector<int>& gids() const { return gids_; }      // overlap-local -> cloud index (0-based)
  // Collective: the owned points' pattern for fields to and from rank 0 in cloud order, chunk by chunk.
  ChunkedGather ownedInChunks(int chunkPoints = ChunkedGather::kDefaultChunkPoints) const {
    return ChunkedGather(comm_, gids_.data(), numOwned(), numGlobal_, chunkPoints);
  }
  // The overlap points' reference coordinates (3 per point) and volumes in overlap-local order, moved out
  // (for the Model, which keeps them); empty after the first call.
  std::vector<double> releaseCoordinates() { return std::move(x_); }
  std::vector<double> releaseVolumes() { return std::move(volume_); }
  const std::vector<BlockRange>& blocks() const { return blocks_; }
  const BondFamily& family() const { return family_; }
  // For a rewrite of the influence before the Model is built (model/PositionAwareInfluence.hpp).
  BondFamily& family() { return family_; }
  const Communicator& comm() const { return comm_; }
  int rank() const { return comm_.rank(); }
  int size() const { return comm_.size(); }

  // overlap[0, ncomp*numOwned) = owned; ghosts filled from their owners. Collective; the first call with a
  // width other than 1 or 3 builds that width's transfer.
  void importToOverlap(const double* owned, double* overlap, int ncomp) const;
  // owned = sum over ranks of overlap contributions to each owned point (owned entries included).
  void exportAdd(const double* overlap, double* owned, int ncomp) const;
  // Collective: rank 0 gets ncomp values per point in cloud order; other ranks get an empty vector. The first
  // call builds the rank-0 maps (every point on rank 0; checkpoints only, Exodus output uses ChunkedGather).
  std::vector<double> gatherToRoot(const double* owned, int ncomp) const;

  double sum(double v) const { return comm_.sum(v); }
  double max(double v) const { return comm_.max(v); }

 private:
  void buildTransfers();  // owned, overlap and rank-0 maps with their Import/Export (GhostTransfers)
  Communicator comm_;
  int numOwned_ = 0, numGlobal_ = 0, numGhostSources_ = 0;
  std::vector<int> gids_;
  std::vector<double> x_, volume_;
  std::vector<BlockRange> blocks_;
  BondFamily family_;
  std::unique_ptr<const GhostTransfers> transfers_;
};

}  // namespace pf
