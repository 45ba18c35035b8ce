#include "GlobalBondOrder.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace pf {

GlobalBondOrder::GlobalBondOrder(const DistributedLayout& layout)
    : layout_(layout), total_(layout.sum(static_cast<double>(layout.family().numBonds()))) {
  constexpr double kChunkValues = 512 * 1024;
  const BondFamily& fam = layout.family();
  int most = 1;
  for (int i = 0; i < fam.numOwned(); ++i) most = std::max(most, fam.offsets[i + 1] - fam.offsets[i]);
  chunkPoints_ = std::max(1, static_cast<int>(kChunkValues / layout.comm().max(static_cast<double>(most))));
}

void GlobalBondOrder::sortBonds(int i, std::vector<std::uint64_t>& bonds) const {
  const BondFamily& fam = layout_.family();
  const std::vector<int>& gids = layout_.gids();
  bonds.clear();
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
    bonds.push_back(static_cast<std::uint64_t>(gids[fam.neighbors[b]]) << 32 | static_cast<std::uint32_t>(b));
  std::sort(bonds.begin(), bonds.end());  // by neighbour cloud index (distinct within a point)
}

ChunkedGather::VariableField GlobalBondOrder::neighbors() const {
  const BondFamily& fam = layout_.family();
  auto scratch = std::make_shared<std::vector<std::uint64_t>>();
  return {[&fam](int i) { return fam.offsets[i + 1] - fam.offsets[i]; },
          [this, scratch](int i, double* out) {
            sortBonds(i, *scratch);
            for (std::uint64_t key : *scratch) *out++ = static_cast<double>(key >> 32);
          }};
}

ChunkedGather::VariableField GlobalBondOrder::values(const double* owned) const {
  const BondFamily& fam = layout_.family();
  auto scratch = std::make_shared<std::vector<std::uint64_t>>();
  return {[&fam](int i) { return fam.offsets[i + 1] - fam.offsets[i]; },
          [this, owned, scratch](int i, double* out) {
            sortBonds(i, *scratch);
            for (std::uint64_t key : *scratch) *out++ = owned[key & 0xffffffffu];
          }};
}

void GlobalBondOrder::locate(int i, int width, const double* theirs, std::vector<std::size_t>& where) const {
  const BondFamily& fam = layout_.family();
  const std::vector<int>& gids = layout_.gids();
  const int count = fam.offsets[i + 1] - fam.offsets[i];
  if (width != count)
    throw std::runtime_error("point " + std::to_string(gids[i] + 1) + " has " + std::to_string(count) + " bonds here, " +
                             std::to_string(width) + " there");
  where.resize(static_cast<std::size_t>(count));
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const double far = gids[fam.neighbors[b]];
    const double* it = std::lower_bound(theirs, theirs + width, far);
    if (it == theirs + width || *it != far)
      throw std::runtime_error("it lacks the bond of points " + std::to_string(gids[i] + 1) + " and " +
                               std::to_string(static_cast<long>(far) + 1));
    where[static_cast<std::size_t>(b - fam.offsets[i])] = static_cast<std::size_t>(it - theirs);
  }
}

}  // namespace pf
