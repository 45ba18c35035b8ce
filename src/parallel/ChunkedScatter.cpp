// ChunkedGather's inverse direction: rank 0 reads a chunk and sends it whole to each rank owning points in
// it; the rank picks its points out by their offsets in the chunk (parallel/ChunkedGather.hpp).
#include <mpi.h>

#include <algorithm>
#include <exception>
#include <stdexcept>

#include "parallel/ChunkedGather.hpp"
#include "parallel/CommunicatorImpl.hpp"

namespace pf {

namespace {
// Apart from the gather's tag (19019): a scatter and a gather never overlap, but a distinct tag makes a
// mismatch a hang in a debugger rather than a silent misread. Rank 0's messages to a rank come in chunk
// order, so the next one from rank 0 is the next chunk this rank owns points in.
constexpr int kScatterTag = 19020;

// Runs f unless an earlier call failed; keeps the first exception, so the exchange goes on to the end.
template <class F>
void guarded(std::exception_ptr& error, F&& f) {
  if (error) return;
  try {
    f();
  } catch (...) {
    error = std::current_exception();
  }
}
}  // namespace

void ChunkedGather::sendChunkToOwners(int k, const std::vector<double>& msg) const {
  for (int r = 1; r < comm_.size(); ++r)
    if (counts_[static_cast<std::size_t>(k) * comm_.size() + r] > 0)
      MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_DOUBLE, r, kScatterTag, comm_.impl().mpi);
}

void ChunkedGather::scatter(int ncomp, const Reader& read, const Putter& put) const {
  std::vector<double> chunk;
  std::exception_ptr error;
  for (int k = 0; k < numChunks_; ++k) {
    const int begin = k * chunk_, count = std::min(chunk_, numGlobal_ - begin);
    chunk.assign(static_cast<std::size_t>(ncomp) * count, 0.0);  // zeros if read fails: the others still get a chunk
    if (comm_.rank() == 0) {
      guarded(error, [&] { read(begin, count, chunk.data()); });
      sendChunkToOwners(k, chunk);
    } else if (ownsIn(k)) {
      MPI_Recv(chunk.data(), static_cast<int>(chunk.size()), MPI_DOUBLE, 0, kScatterTag, comm_.impl().mpi,
               MPI_STATUS_IGNORE);
    }
    for (int e = chunkStart_[k]; e < chunkStart_[k + 1]; ++e)
      guarded(error, [&] { put(order_[e], chunk.data() + static_cast<std::size_t>(ncomp) * offsetInChunk_[e]); });
  }
  if (error) std::rethrow_exception(error);
}

void ChunkedGather::scatterVariable(int nblocks, const VariableReader& read, const VariablePutter& put) const {
  std::vector<double> msg;
  std::vector<std::size_t> start;
  std::vector<const double*> blocks(static_cast<std::size_t>(nblocks));
  std::exception_ptr error;
  for (int k = 0; k < numChunks_; ++k) {
    const int begin = k * chunk_, count = std::min(chunk_, numGlobal_ - begin);
    if (comm_.rank() == 0) {
      msg.clear();
      guarded(error, [&] { read(begin, count, msg); });
      if (error) msg.assign(static_cast<std::size_t>(count), 0.0);  // zero widths: a well-formed, empty chunk
      sendChunkToOwners(k, msg);
    } else if (ownsIn(k)) {
      MPI_Status status;
      MPI_Probe(0, kScatterTag, comm_.impl().mpi, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &n);
      msg.resize(static_cast<std::size_t>(n));
      MPI_Recv(msg.data(), n, MPI_DOUBLE, 0, kScatterTag, comm_.impl().mpi, MPI_STATUS_IGNORE);
    } else {
      continue;
    }
    start.assign(static_cast<std::size_t>(count) + 1, 0);
    for (int p = 0; p < count; ++p) start[p + 1] = start[p] + static_cast<std::size_t>(msg[p]);
    const std::size_t total = start.back();
    if (msg.size() != static_cast<std::size_t>(count) + total * nblocks) {  // rank 0's reader broke its contract
      guarded(error, [&] { throw std::logic_error("ChunkedGather::scatterVariable: a chunk of the wrong length"); });
      continue;
    }
    for (int e = chunkStart_[k]; e < chunkStart_[k + 1]; ++e) {
      const std::size_t p = static_cast<std::size_t>(offsetInChunk_[e]);
      for (int b = 0; b < nblocks; ++b) blocks[b] = msg.data() + count + total * b + start[p];
      guarded(error, [&] { put(order_[e], static_cast<int>(start[p + 1] - start[p]), blocks); });
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace pf
