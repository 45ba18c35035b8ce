#include "GhostTransfers.hpp"

namespace pf {

std::unique_ptr<GhostTransfers> makeGhostTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                   int numGlobal) {
  return makeTpetraTransfers(comm, numOwned, gids, numGlobal);
}

}  // namespace pf
