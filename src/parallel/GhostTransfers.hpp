#pragma once
// The data movement of a DistributedLayout: owned values to the ghosts (import), ghost contributions added back
// to their owners (export), and every point's values to rank 0 in cloud order (checkpoints). Values are
// interleaved, ncomp per point, in the layout's owned / overlap order. Two implementations during the move off
// Epetra (issue 20): Tpetra's maps, Import and Export (the default) and Epetra's (kept for comparison until
// Epetra goes); CMake's PERIFORGE_TRANSFERS picks the one makeGhostTransfers builds. Every call is collective; a width's maps are built on its first use.
#include <memory>
#include <string>
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

// gids: cloud index of each overlap point, the numOwned owned ones first. kind: "Epetra", "Tpetra" or "" (the
// build's default, PERIFORGE_TRANSFERS).
std::unique_ptr<GhostTransfers> makeGhostTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                   int numGlobal, const std::string& kind = "");
std::unique_ptr<GhostTransfers> makeEpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                    int numGlobal);
std::unique_ptr<GhostTransfers> makeTpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                    int numGlobal);

}  // namespace pf
