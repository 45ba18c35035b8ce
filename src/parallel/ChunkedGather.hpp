#pragma once
// Rank 0 receives distributed point fields in cloud order one chunk at a time, never a whole field: chunk k
// is cloud indices [k*C, min((k+1)*C, N)); each rank sends only its owned points of that chunk (offsets in
// the chunk, then values), so rank 0 holds one chunk's values beside its own. The pattern is built once.
#include <functional>
#include <vector>

#include "parallel/Communicator.hpp"

namespace pf {

class ChunkedGather {
 public:
  // 32 768 points: rank 0 then buffers at most 32768 * (2 * values per point + 1) doubles, 5.5 MB for 10
  // values (a few vectors and scalars), well inside the 80 MB allowance; each message is then
  // hundreds of kB, far past MPI's eager limit, so per-chunk latency costs nothing next to the data.
  static constexpr int kDefaultChunkPoints = 32768;

  // A field's ncomp values of owned point `local` (owned-local index) into out: asked for as each chunk is
  // packed, so no rank makes a copy of its whole share either.
  struct Field {
    std::function<void(int local, double* out)> values;
    int ncomp;
  };
  // values[f]: fields[f].ncomp * count doubles for cloud indices [begin, begin + count) (rank 0 only).
  using Writer = std::function<void(int begin, int count, const std::vector<const double*>& values)>;

  // Collective. ownedGids: the cloud index (0-based) of each of this rank's numOwned points; every index
  // in [0, numGlobal) is owned by exactly one rank (std::logic_error on every rank otherwise).
  ChunkedGather(const Communicator& comm, const int* ownedGids, int numOwned, int numGlobal,
                int chunkPoints = kDefaultChunkPoints);

  int numChunks() const { return numChunks_; }
  int chunkPoints() const { return chunk_; }
  int numGlobal() const { return numGlobal_; }

  // Collective: rank 0 calls write once per chunk, in cloud order, with every field's values of that
  // chunk; the other ranks only send. If write throws, the remaining chunks are still received (not
  // written), so no rank is left waiting, and rank 0 rethrows the first error at the end.
  void gather(const std::vector<Field>& fields, const Writer& write) const;

 private:
  void sendChunks(const std::vector<Field>& fields, int nvals) const;
  void receiveChunks(const std::vector<Field>& fields, int nvals, const Writer& write) const;

  Communicator comm_;
  int numGlobal_ = 0, chunk_ = 0, numChunks_ = 0;
  std::vector<int> order_;        // owned-local indices sorted by cloud index
  std::vector<int> offsetInChunk_;  // per entry of order_: its cloud index minus its chunk's first index
  std::vector<int> chunkStart_;   // chunk k's entries of order_: [chunkStart_[k], chunkStart_[k + 1])
  std::vector<int> counts_;       // rank 0: counts_[k * size + r] = points rank r owns in chunk k
};

}  // namespace pf
