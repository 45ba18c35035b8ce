#include "GhostTransfers.hpp"

#include <stdexcept>

namespace pf {

#ifndef PERIFORGE_TRANSFERS
#define PERIFORGE_TRANSFERS "Tpetra"
#endif

std::unique_ptr<GhostTransfers> makeGhostTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                   int numGlobal, const std::string& kind) {
  const std::string k = kind.empty() ? std::string(PERIFORGE_TRANSFERS) : kind;
  if (k == "Epetra") return makeEpetraTransfers(comm, numOwned, gids, numGlobal);
  if (k == "Tpetra") return makeTpetraTransfers(comm, numOwned, gids, numGlobal);
  throw std::invalid_argument("ghost transfers: unknown kind '" + k + "' (Epetra or Tpetra)");
}

}  // namespace pf
