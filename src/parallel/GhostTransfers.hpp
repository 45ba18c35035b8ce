#pragma once
// The data movement of a DistributedLayout: owned values to the ghosts (import), ghost contributions added back
// to their owners (export), and every point's values to rank 0 in cloud order (checkpoints). Values are
// interleaved, ncomp per point, in the layout's owned / overlap order. Implemented on Tpetra's maps, Import and
// Export (issue 20; Epetra's, which it replaced, gave the same bits). Every call is collective; a width's maps
// are built on its first use.
#include <memory>
#include <vector>

#include "parallel/Communicator.hpp"

namespace pf {

class GhostTransfers {
 public:
  virtual ~GhostTransfers() = default;
  virtual void importToOverlap(const double* owned, double* overlap, int ncomp) const = 0;
  virtual void exportAdd(const double* overlap, double* owned, int ncomp) const = 0;  // owned = sum of overlap copies
  virtual std::vector<double> gatherToRoot(const double* owned, int ncomp) const = 0;  // empty off rank 0
};

// gids: cloud index of each overlap point, the numOwned owned ones first.
std::unique_ptr<GhostTransfers> makeGhostTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                   int numGlobal);
std::unique_ptr<GhostTransfers> makeTpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                    int numGlobal);

}  // namespace pf
