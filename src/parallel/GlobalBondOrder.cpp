#include "GlobalBondOrder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pf {

GlobalBondOrder::GlobalBondOrder(const DistributedLayout& layout) : layout_(layout) {
  const BondFamily& fam = layout.family();
  const std::vector<int>& gids = layout.gids();
  std::vector<double> nodes, far;  // (cloud index, bond count) per owned point; neighbours, sorted per point
  for (int i = 0; i < fam.numOwned(); ++i) {
    const std::size_t begin = sorted_.size();
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) sorted_.push_back(static_cast<std::size_t>(b));
    std::sort(sorted_.begin() + static_cast<long>(begin), sorted_.end(), [&](std::size_t a, std::size_t b) {
      return gids[fam.neighbors[a]] < gids[fam.neighbors[b]];
    });
    nodes.push_back(gids[i]);
    nodes.push_back(fam.offsets[i + 1] - fam.offsets[i]);
    for (std::size_t k = begin; k < sorted_.size(); ++k) far.push_back(gids[fam.neighbors[sorted_[k]]]);
  }
  const std::vector<double> allNodes = layout.comm().gatherToRoot(nodes);
  const std::vector<double> allFar = layout.comm().gatherToRoot(far);
  if (layout.rank() != 0) return;
  counts_.assign(static_cast<std::size_t>(layout.numGlobal()), 0.0);
  for (std::size_t k = 0; k < allNodes.size(); k += 2) counts_[static_cast<std::size_t>(allNodes[k])] = allNodes[k + 1];
  std::vector<std::size_t> offset(counts_.size() + 1, 0);
  for (std::size_t g = 0; g < counts_.size(); ++g) offset[g + 1] = offset[g] + static_cast<std::size_t>(counts_[g]);
  neighbors_.assign(offset.back(), 0.0);
  placement_.resize(allFar.size());
  std::size_t p = 0;  // the gathered stream: rank by rank, point by point, bond by bond
  for (std::size_t k = 0; k < allNodes.size(); k += 2) {
    const std::size_t g = static_cast<std::size_t>(allNodes[k]);
    for (std::size_t j = 0; j < static_cast<std::size_t>(allNodes[k + 1]); ++j, ++p) {
      placement_[p] = offset[g] + j;
      neighbors_[offset[g] + j] = allFar[p];
    }
  }
}

std::vector<double> GlobalBondOrder::gatherToRoot(const double* owned) const {
  std::vector<double> mine(sorted_.size());
  for (std::size_t k = 0; k < sorted_.size(); ++k) mine[k] = owned[sorted_[k]];
  const std::vector<double> all = layout_.comm().gatherToRoot(mine);
  std::vector<double> out(all.size());
  for (std::size_t p = 0; p < all.size(); ++p) out[placement_[p]] = all[p];
  return out;
}

std::vector<std::size_t> GlobalBondOrder::locate(const std::vector<double>& counts,
                                                 const std::vector<double>& neighbors) const {
  const BondFamily& fam = layout_.family();
  const std::vector<int>& gids = layout_.gids();
  if (counts.size() != static_cast<std::size_t>(layout_.numGlobal()))
    throw std::runtime_error("it has bonds of " + std::to_string(counts.size()) + " points, this body " +
                             std::to_string(layout_.numGlobal()));
  std::vector<std::size_t> offset(counts.size() + 1, 0);
  for (std::size_t g = 0; g < counts.size(); ++g) offset[g + 1] = offset[g] + static_cast<std::size_t>(counts[g]);
  if (offset.back() != neighbors.size()) throw std::runtime_error("its bond counts and neighbours disagree");
  std::vector<std::size_t> where(fam.numBonds());
  for (int i = 0; i < fam.numOwned(); ++i) {
    const auto g = static_cast<std::size_t>(gids[i]);
    const auto first = neighbors.begin() + static_cast<long>(offset[g]);
    const auto last = neighbors.begin() + static_cast<long>(offset[g + 1]);
    if (counts[g] != fam.offsets[i + 1] - fam.offsets[i])
      throw std::runtime_error("point " + std::to_string(g + 1) + " has " + std::to_string(fam.offsets[i + 1] - fam.offsets[i]) +
                               " bonds here, " + std::to_string(static_cast<long>(counts[g])) + " there");
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      const double far = gids[fam.neighbors[b]];
      const auto it = std::lower_bound(first, last, far);
      if (it == last || *it != far)
        throw std::runtime_error("it lacks the bond of points " + std::to_string(g + 1) + " and " +
                                 std::to_string(static_cast<long>(far) + 1));
      where[static_cast<std::size_t>(b)] = static_cast<std::size_t>(it - neighbors.begin());
    }
  }
  return where;
}

}  // namespace pf
