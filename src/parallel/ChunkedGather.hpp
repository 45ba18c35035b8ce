#pragma once
// Rank 0 receives distributed point fields in cloud order one chunk at a time, never a whole field: chunk k
// is cloud indices [k*C, min((k+1)*C, N)); each rank sends only its owned points of that chunk (offsets in
// the chunk, then values), so rank 0 holds one chunk's values beside its own. The pattern is built once.
// scatter is the inverse (rank 0 reads a chunk, the ranks owning points in it get it); the Variable forms
// carry a number of values per point that differs from point to point (a point's bonds, say).
#include <cstddef>
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

  // width(local) values per point; values(local, out) writes them.
  struct VariableField {
    std::function<int(int local)> width;
    std::function<void(int local, double* out)> values;
  };
  // values: the chunk's n values, point after point in cloud order (rank 0 only).
  using VariableWriter = std::function<void(int begin, int count, const double* values, std::size_t n)>;
  // Collective, as gather (errors likewise), for one field of variable width.
  void gatherVariable(const VariableField& field, const VariableWriter& write) const;

  // Rank 0: fill out with the ncomp * count values of cloud indices [begin, begin + count).
  using Reader = std::function<void(int begin, int count, double* out)>;
  // Every rank: the ncomp values of owned point `local`.
  using Putter = std::function<void(int local, const double* in)>;
  // Collective: read is called once per chunk in cloud order, put once per owned point. An exception from
  // read or put does not stop the exchange (no rank is left waiting); the rank rethrows its first at the
  // end, so callers wrap this in collectively() to fail on every rank.
  void scatter(int ncomp, const Reader& read, const Putter& put) const;

  // Rank 0: the chunk's widths (count of them) and then nblocks blocks of sum(widths) values each, every
  // block point after point in cloud order (a point's bonds' neighbours, then each per-bond field).
  using VariableReader = std::function<void(int begin, int count, std::vector<double>& widthsAndBlocks)>;
  // Every rank: owned point `local`'s width and, per block, a pointer to its `width` values.
  using VariablePutter = std::function<void(int local, int width, const std::vector<const double*>& blocks)>;
  // Collective, as scatter, for nblocks fields that share one variable width per point.
  void scatterVariable(int nblocks, const VariableReader& read, const VariablePutter& put) const;

 private:
  void sendChunks(const std::vector<Field>& fields, int nvals) const;
  void receiveChunks(const std::vector<Field>& fields, int nvals, const Writer& write) const;
  void sendVariable(const VariableField& field) const;
  void receiveVariable(const VariableField& field, const VariableWriter& write) const;
  // Rank 0: sends chunk k's message to every rank owning points in it (chunk-order sends, so each rank's
  // next message from 0 is its next chunk).
  void sendChunkToOwners(int k, const std::vector<double>& msg) const;
  bool ownsIn(int k) const { return chunkStart_[k + 1] > chunkStart_[k]; }

  Communicator comm_;
  int numGlobal_ = 0, chunk_ = 0, numChunks_ = 0;
  std::vector<int> order_;        // owned-local indices sorted by cloud index
  std::vector<int> offsetInChunk_;  // per entry of order_: its cloud index minus its chunk's first index
  std::vector<int> chunkStart_;   // chunk k's entries of order_: [chunkStart_[k], chunkStart_[k + 1])
  std::vector<int> counts_;       // rank 0: counts_[k * size + r] = points rank r owns in chunk k
};

}  // namespace pf
