#pragma once
// The bonds of the whole body in one order that does not depend on the partition: by point (cloud index),
// then by the neighbour's cloud index. Per-bond data written in this order at one rank count can be read
// at any other, where the same bond may sit at another local position (checkpoints, src/app).
#include <cstddef>
#include <vector>

#include "parallel/DistributedLayout.hpp"

namespace pf {

class GlobalBondOrder {
 public:
  explicit GlobalBondOrder(const DistributedLayout& layout);  // collective

  // Rank 0: the bond count of every point (cloud order) and every bond's neighbour (cloud index), in the
  // global order; empty on the other ranks. Doubles (exact for counts below 2^53) to sit beside the data.
  const std::vector<double>& counts() const { return counts_; }
  const std::vector<double>& neighbors() const { return neighbors_; }
  // Collective: rank 0 gets the value of every bond (one per bond of the owned points, local bond order) in
  // the global order; the others get an empty vector.
  std::vector<double> gatherToRoot(const double* owned) const;
  // Local: the position of each local bond in the global order that counts and neighbors describe (another
  // run's); std::runtime_error naming the first bond of this body that order lacks.
  std::vector<std::size_t> locate(const std::vector<double>& counts, const std::vector<double>& neighbors) const;

 private:
  const DistributedLayout& layout_;
  std::vector<std::size_t> sorted_;     // local bond indices, each point's bonds by neighbour cloud index
  std::vector<std::size_t> placement_;  // rank 0: global position of the p-th gathered bond
  std::vector<double> counts_, neighbors_;
};

}  // namespace pf
