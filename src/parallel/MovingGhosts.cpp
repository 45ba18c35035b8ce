#include "MovingGhosts.hpp"

#include <algorithm>

#include "parallel/PointExchange.hpp"

namespace pf {

MovingGhosts::~MovingGhosts() = default;

void MovingGhosts::rebuild(const PointCloud& candidates, double pad) {
  ghosts_ = exchangeNearBoxes(layout_.comm(), candidates, pad);
  // The transfer's overlap: every owned point of the layout, then the ghosts.
  std::vector<int> gids(layout_.gids().begin(), layout_.gids().begin() + layout_.numOwned());
  gids.insert(gids.end(), ghosts_.gid.begin(), ghosts_.gid.end());
  transfers_ = makeGhostTransfers(layout_.comm(), layout_.numOwned(), gids, layout_.numGlobal());
}

void MovingGhosts::update(const double* owned, double* ghostValues, int ncomp) const {
  const std::size_t numOwned = static_cast<std::size_t>(layout_.numOwned()) * ncomp;
  overlap_.resize(numOwned + ghosts_.gid.size() * ncomp);
  transfers_->importToOverlap(owned, overlap_.data(), ncomp);
  std::copy(overlap_.begin() + static_cast<long>(numOwned), overlap_.end(), ghostValues);
}

}  // namespace pf
