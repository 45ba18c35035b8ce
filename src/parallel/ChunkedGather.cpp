#include "ChunkedGather.hpp"

#include <mpi.h>

#include <algorithm>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <string>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {

namespace {
// One tag for every chunk message: MPI keeps messages from one sender in order, and rank 0 receives the
// chunks in order, so chunk k's message from rank r is the next one from r. Trilinos' tags are far apart.
constexpr int kTag = 19019;
}  // namespace

ChunkedGather::ChunkedGather(const Communicator& comm, const int* ownedGids, int numOwned, int numGlobal,
                             int chunkPoints)
    : comm_(comm), numGlobal_(numGlobal), chunk_(chunkPoints) {
  if (chunkPoints < 1) throw std::logic_error("ChunkedGather: chunk size must be at least 1");
  numChunks_ = numGlobal_ == 0 ? 0 : (numGlobal_ - 1) / chunk_ + 1;
  order_.resize(numOwned);
  std::iota(order_.begin(), order_.end(), 0);
  std::sort(order_.begin(), order_.end(), [&](int a, int b) { return ownedGids[a] < ownedGids[b]; });
  bool bad = false;
  offsetInChunk_.resize(numOwned);
  std::vector<int> mine(numChunks_, 0);
  for (int e = 0; e < numOwned; ++e) {
    const int g = ownedGids[order_[e]];
    if (g < 0 || g >= numGlobal_) { bad = true; break; }
    ++mine[g / chunk_];
    offsetInChunk_[e] = g % chunk_;
  }
  chunkStart_.assign(numChunks_ + 1, 0);
  for (int k = 0; k < numChunks_; ++k) chunkStart_[k + 1] = chunkStart_[k] + mine[k];
  const int size = comm_.size();
  if (comm_.rank() == 0) counts_.resize(static_cast<std::size_t>(numChunks_) * size);
  std::vector<int> all(comm_.rank() == 0 ? static_cast<std::size_t>(numChunks_) * size : 0);
  MPI_Gather(mine.data(), numChunks_, MPI_INT, all.data(), numChunks_, MPI_INT, 0, comm_.impl().mpi);
  for (int r = 0; r < static_cast<int>(all.size()) / std::max(numChunks_, 1); ++r)
    for (int k = 0; k < numChunks_; ++k) counts_[static_cast<std::size_t>(k) * size + r] = all[r * numChunks_ + k];
  if (comm_.rank() == 0)  // each chunk's points owned exactly once (counts must add up; duplicates show in gather)
    for (int k = 0; k < numChunks_ && !bad; ++k) {
      const int expected = std::min(chunk_, numGlobal_ - k * chunk_);
      int got = 0;
      for (int r = 0; r < size; ++r) got += counts_[static_cast<std::size_t>(k) * size + r];
      bad = got != expected;
    }
  if (comm_.anyFailed(bad))
    throw std::logic_error("ChunkedGather: the owned points do not cover the cloud's " + std::to_string(numGlobal_) +
                           " points once");
}

void ChunkedGather::gather(const std::vector<Field>& fields, const Writer& write) const {
  int nvals = 0;
  for (const Field& f : fields) nvals += f.ncomp;
  if (comm_.rank() == 0)
    receiveChunks(fields, nvals, write);
  else
    sendChunks(fields, nvals);
}

// One message per chunk this rank has points in: their offsets in the chunk (exact as doubles), then each
// field's values point by point.
void ChunkedGather::sendChunks(const std::vector<Field>& fields, int nvals) const {
  std::vector<double> msg;
  for (int k = 0; k < numChunks_; ++k) {
    const int b = chunkStart_[k], m = chunkStart_[k + 1] - b;
    if (m == 0) continue;
    msg.resize(static_cast<std::size_t>(m) * (1 + nvals));
    double* out = msg.data();
    for (int e = b; e < b + m; ++e) *out++ = offsetInChunk_[e];
    for (const Field& f : fields)
      for (int e = b; e < b + m; ++e, out += f.ncomp) f.values(order_[e], out);
    MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_DOUBLE, 0, kTag, comm_.impl().mpi);
  }
}

void ChunkedGather::receiveChunks(const std::vector<Field>& fields, int nvals, const Writer& write) const {
  const int size = comm_.size();
  std::vector<std::vector<double>> buf(fields.size());
  std::vector<const double*> values(fields.size());
  for (std::size_t f = 0; f < fields.size(); ++f) buf[f].resize(static_cast<std::size_t>(fields[f].ncomp) * chunk_);
  std::vector<double> msg;
  std::exception_ptr error;
  for (int k = 0; k < numChunks_; ++k) {
    const int begin = k * chunk_, count = std::min(chunk_, numGlobal_ - begin);
    for (std::size_t f = 0; f < fields.size(); ++f) {  // own points straight from the field
      const int nc = fields[f].ncomp;
      for (int e = chunkStart_[k]; e < chunkStart_[k + 1]; ++e)
        fields[f].values(order_[e], buf[f].data() + static_cast<std::size_t>(nc) * offsetInChunk_[e]);
    }
    for (int r = 1; r < size; ++r) {
      const int m = counts_[static_cast<std::size_t>(k) * size + r];
      if (m == 0) continue;
      msg.resize(static_cast<std::size_t>(m) * (1 + nvals));
      MPI_Recv(msg.data(), static_cast<int>(msg.size()), MPI_DOUBLE, r, kTag, comm_.impl().mpi, MPI_STATUS_IGNORE);
      const double* in = msg.data() + m;
      for (std::size_t f = 0; f < fields.size(); ++f) {
        const int nc = fields[f].ncomp;
        for (int e = 0; e < m; ++e, in += nc)
          std::copy_n(in, nc, buf[f].data() + static_cast<std::size_t>(nc) * static_cast<int>(msg[e]));
      }
    }
    if (error) continue;
    for (std::size_t f = 0; f < fields.size(); ++f) values[f] = buf[f].data();
    try {
      write(begin, count, values);
    } catch (...) {
      error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

void ChunkedGather::gatherVariable(const VariableField& field, const VariableWriter& write) const {
  if (comm_.rank() == 0)
    receiveVariable(field, write);
  else
    sendVariable(field);
}

// One message per chunk this rank has points in: their offsets in the chunk, their widths, then the values.
void ChunkedGather::sendVariable(const VariableField& field) const {
  std::vector<double> msg;
  for (int k = 0; k < numChunks_; ++k) {
    const int b = chunkStart_[k], m = chunkStart_[k + 1] - b;
    if (m == 0) continue;
    msg.assign(static_cast<std::size_t>(2 * m), 0.0);
    for (int e = b; e < b + m; ++e) {
      msg[e - b] = offsetInChunk_[e];
      msg[m + e - b] = field.width(order_[e]);
    }
    for (int e = b; e < b + m; ++e) {
      const std::size_t at = msg.size();
      msg.resize(at + static_cast<std::size_t>(msg[m + e - b]));
      field.values(order_[e], msg.data() + at);
    }
    MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_DOUBLE, 0, kTag, comm_.impl().mpi);
  }
}

void ChunkedGather::receiveVariable(const VariableField& field, const VariableWriter& write) const {
  const int size = comm_.size();
  std::vector<std::vector<double>> msgs(static_cast<std::size_t>(size));
  std::vector<std::size_t> start;  // each point of the chunk: where its values begin
  std::vector<double> values;
  std::exception_ptr error;
  for (int k = 0; k < numChunks_; ++k) {
    const int begin = k * chunk_, count = std::min(chunk_, numGlobal_ - begin);
    start.assign(static_cast<std::size_t>(count) + 1, 0);
    for (int e = chunkStart_[k]; e < chunkStart_[k + 1]; ++e) start[offsetInChunk_[e] + 1] = field.width(order_[e]);
    for (int r = 1; r < size; ++r) {
      const int m = counts_[static_cast<std::size_t>(k) * size + r];
      if (m == 0) continue;
      MPI_Status status;
      MPI_Probe(r, kTag, comm_.impl().mpi, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &n);
      msgs[r].resize(static_cast<std::size_t>(n));
      MPI_Recv(msgs[r].data(), n, MPI_DOUBLE, r, kTag, comm_.impl().mpi, MPI_STATUS_IGNORE);
      for (int e = 0; e < m; ++e) start[static_cast<std::size_t>(msgs[r][e]) + 1] = msgs[r][m + e];
    }
    for (int p = 0; p < count; ++p) start[p + 1] += start[p];
    values.resize(start.back());
    for (int e = chunkStart_[k]; e < chunkStart_[k + 1]; ++e) field.values(order_[e], values.data() + start[offsetInChunk_[e]]);
    for (int r = 1; r < size; ++r) {
      const int m = counts_[static_cast<std::size_t>(k) * size + r];
      const double* in = msgs[r].data() + 2 * m;
      for (int e = 0; e < m; ++e) {
        const std::size_t p = static_cast<std::size_t>(msgs[r][e]), w = start[p + 1] - start[p];
        std::copy_n(in, w, values.data() + start[p]);
        in += w;
      }
    }
    if (error) continue;
    try {
      write(begin, count, values.data(), values.size());
    } catch (...) {
      error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace pf
