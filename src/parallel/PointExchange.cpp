#include "PointExchange.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {
namespace {

// gid, x, y, z, volume, block, node-set tags, sending rank: doubles hold ints below 2^53 exactly.
constexpr int kWidth = 8;

}  // namespace

PointCloud withoutPoints(const PointCloud& cloud) {
  PointCloud c;
  c.numGlobal = cloud.numGlobal;
  c.planar = cloud.planar;
  c.thickness = cloud.thickness;
  c.spacing = cloud.spacing;
  c.influence = cloud.influence;
  c.cell = cloud.cell;
  c.partialVolume = cloud.partialVolume;
  for (const auto& kv : cloud.generatedNodeSets) c.generatedNodeSets[kv.first];
  return c;
}

PointCloud exchangePoints(const Communicator& comm, const PointCloud& points, const std::vector<int>& index,
                          const std::vector<int>& dest, std::vector<int>* from) {
  const MPI_Comm mpi = comm.impl().mpi;
  const int size = comm.size();
  if (index.size() != dest.size()) throw std::logic_error("exchangePoints: index and dest differ in length");
  if (points.generatedNodeSets.size() > 50) throw std::logic_error("exchangePoints: more than 50 generated node sets");
  // A point's generated sets as bits, in the map's (name) order.
  std::vector<double> tags(points.size(), 0.0);
  double bit = 1.0;
  for (const auto& kv : points.generatedNodeSets) {
    for (int g : kv.second) {
      const auto it = std::lower_bound(points.gid.begin(), points.gid.end(), g);
      tags[it - points.gid.begin()] += bit;
    }
    bit *= 2.0;
  }
  std::vector<int> order(index.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dest[a] < dest[b]; });
  // Counts and displacements in points (one MPI datatype of kWidth doubles), so MPI's int counts allow 2^31
  // points per rank and exchange (the 32-bit id limit) rather than 2^31 doubles.
  std::vector<int> sendCounts(size, 0), recvCounts(size, 0), sendDispl(size, 0), recvDispl(size, 0);
  for (int d : dest) ++sendCounts[d];
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, mpi);
  for (int r = 1; r < size; ++r) {
    sendDispl[r] = sendDispl[r - 1] + sendCounts[r - 1];
    recvDispl[r] = recvDispl[r - 1] + recvCounts[r - 1];
  }
  std::vector<double> send;
  send.reserve(static_cast<std::size_t>(kWidth) * index.size());
  for (int k : order) {
    const int p = index[k];
    send.insert(send.end(), {static_cast<double>(points.gid[p]), points.x[3 * p], points.x[3 * p + 1],
                             points.x[3 * p + 2], points.volume[p], static_cast<double>(points.block[p]), tags[p],
                             static_cast<double>(comm.rank())});
  }
  std::vector<double>().swap(tags);
  std::vector<double> recv(kWidth * (static_cast<std::size_t>(recvDispl[size - 1]) + recvCounts[size - 1]));
  MPI_Datatype point;
  MPI_Type_contiguous(kWidth, MPI_DOUBLE, &point);
  MPI_Type_commit(&point);
  MPI_Alltoallv(send.data(), sendCounts.data(), sendDispl.data(), point, recv.data(), recvCounts.data(),
                recvDispl.data(), point, mpi);
  MPI_Type_free(&point);
  std::vector<double>().swap(send);

  const int n = static_cast<int>(recv.size() / kWidth);
  std::vector<int> byGid(n);
  std::iota(byGid.begin(), byGid.end(), 0);
  std::sort(byGid.begin(), byGid.end(), [&](int a, int b) { return recv[kWidth * a] < recv[kWidth * b]; });
  PointCloud out = withoutPoints(points);
  out.gid.reserve(n), out.x.reserve(3 * n), out.volume.reserve(n), out.block.reserve(n);
  if (from) from->assign(n, 0);
  for (int k = 0; k < n; ++k) {
    const double* r = &recv[static_cast<std::size_t>(kWidth) * byGid[k]];
    out.gid.push_back(static_cast<int>(r[0]));
    out.x.insert(out.x.end(), r + 1, r + 4);
    out.volume.push_back(r[4]);
    out.block.push_back(static_cast<int>(r[5]));
    auto tag = static_cast<long long>(r[6]);
    for (auto& kv : out.generatedNodeSets) {
      if (tag & 1) kv.second.push_back(out.gid.back());
      tag >>= 1;
    }
    if (from) (*from)[k] = static_cast<int>(r[7]);
  }
  return out;
}

PointCloud exchangeNearBoxes(const Communicator& comm, const PointCloud& owned, double pad, std::vector<int>* from) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int i = 0; i < owned.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], owned.x[3 * i + d]);
      hi[d] = std::max(hi[d], owned.x[3 * i + d]);
    }
  std::vector<double> box(7, 0.0);  // lo - pad, hi + pad, and whether the rank owns any point
  if (owned.size() > 0) {
    for (int d = 0; d < 3; ++d) box[d] = lo[d] - pad, box[3 + d] = hi[d] + pad;
    box[6] = 1.0;
  }
  const std::vector<double> boxes = comm.allGather(box);
  std::vector<int> index, dest;
  for (int q = 0; q < comm.size(); ++q) {
    const double* b = &boxes[7 * q];
    if (q == comm.rank() || b[6] == 0.0) continue;
    bool overlaps = true;  // only ranks whose box meets this rank's points are scanned: O(owned x neighbours)
    for (int d = 0; d < 3; ++d) overlaps = overlaps && hi[d] >= b[d] && lo[d] <= b[3 + d];
    if (!overlaps) continue;
    for (int i = 0; i < owned.size(); ++i) {
      bool inside = true;
      for (int d = 0; d < 3 && inside; ++d) inside = owned.x[3 * i + d] >= b[d] && owned.x[3 * i + d] <= b[3 + d];
      if (inside) index.push_back(i), dest.push_back(q);
    }
  }
  return exchangePoints(comm, owned, index, dest, from);
}

}  // namespace pf
