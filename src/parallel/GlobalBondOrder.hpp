#pragma once
// The bonds of the whole body in one order that does not depend on the partition: by point (cloud index),
// then by the neighbour's cloud index. Per-bond data written in this order at one rank count can be read
// at any other, where the same bond may sit at another local position (checkpoints, src/app). Each point's
// bonds travel as one variable-width entry of a ChunkedGather, so no rank holds the whole body's bonds.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "parallel/ChunkedGather.hpp"
#include "parallel/DistributedLayout.hpp"

namespace pf {

class GlobalBondOrder {
 public:
  explicit GlobalBondOrder(const DistributedLayout& layout);  // collective (the bond total)

  double total() const { return total_; }  // bonds of the whole body
  // Points per chunk for a ChunkedGather of per-bond values: about 512 Ki values (4 MB) per chunk at the
  // largest bond count any point has, so a rank's chunk buffers stay a few MB however many bonds a point
  // has (a 32 Ki-point chunk of 120-bond points would be 30 MB per buffer).
  int chunkPoints() const { return chunkPoints_; }
  // An owned point's bonds in the global order, for ChunkedGather::gatherVariable: the neighbours' cloud
  // indices, or the values of a per-bond array (one per bond of the owned points, local bond order).
  ChunkedGather::VariableField neighbors() const;
  ChunkedGather::VariableField values(const double* owned) const;
  // Owned point i's bonds found in another run's list of its neighbours (theirs: width cloud indices,
  // ascending): where[b - first] is the position in theirs of i's local bond b. std::runtime_error naming
  // the point whose bond count differs, or the first bond theirs lacks.
  void locate(int i, int width, const double* theirs, std::vector<std::size_t>& where) const;

 private:
  // Point i's bonds in the global order, each as neighbour cloud index << 32 | local bond index (one integer
  // compare). Sorted when asked, not stored: a stored order cost 8 bytes a bond for the whole run.
  void sortBonds(int i, std::vector<std::uint64_t>& bonds) const;
  const DistributedLayout& layout_;
  double total_ = 0.0;
  int chunkPoints_ = 1;
};

}  // namespace pf
