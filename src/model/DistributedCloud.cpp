#include "DistributedCloud.hpp"

#include <algorithm>
#include <numeric>

#include "core/InputError.hpp"
#include "discretization/DuplicatePoints.hpp"
#include "parallel/Collective.hpp"
#include "parallel/PointExchange.hpp"

namespace pf {
namespace {

// Exclusive prefix sums of one count per rank, and their total.
std::vector<long long> offsets(const Communicator& comm, long long mine, long long* total) {
  const std::vector<double> all = comm.allGather({static_cast<double>(mine)});
  std::vector<long long> first(all.size() + 1, 0);
  for (std::size_t r = 0; r < all.size(); ++r) first[r + 1] = first[r] + static_cast<long long>(all[r]);
  *total = first.back();
  return first;
}

// Each rank reads its byte range; the points then move to the slabs the generators would give.
PointCloud textFileSlab(const DiscretizationSpec& d, const std::string& inputFile, const Communicator& comm) {
  const int rank = comm.rank(), size = comm.size();
  MeshFileRange range;
  collectively(comm, [&] { range = meshFileRange(d, inputFile, rank, size); });
  long long lines = 0, n = 0;
  const long long firstLine = offsets(comm, range.lines, &lines)[rank];
  PointCloud part;
  collectively(comm, [&] { part = readMeshRange(d, inputFile, range, firstLine); });
  const long long first = offsets(comm, part.size(), &n)[rank];
  if (n == 0) throw InputError(inputFile + ": Discretization/Input Mesh File: mesh file '" + d.meshFile + "' holds no points");
  part.numGlobal = n;
  std::vector<int> index(part.size()), dest(part.size());
  for (int i = 0; i < part.size(); ++i) {
    const long long g = first + i;
    part.gid.push_back(static_cast<int>(g));
    int r = static_cast<int>(g * size / n);
    while (n * (r + 1) / size <= g) ++r;
    while (n * r / size > g) --r;
    index[i] = i, dest[i] = r;
  }
  return exchangePoints(comm, part, index, dest);
}

}  // namespace

PointCloud buildSlab(const DiscretizationSpec& spec, const std::string& inputFile, const Communicator& comm) {
  if (spec.type == DiscretizationSpec::Type::TextFile) return textFileSlab(spec, inputFile, comm);
  PointCloud slab;
  collectively(comm, [&] { slab = buildDiscretization(spec, inputFile, comm.rank(), comm.size()); });
  return slab;
}

std::set<int> blockIdsOf(const PointCloud& slab, const Communicator& comm) {
  const std::set<int> mine(slab.block.begin(), slab.block.end());
  const std::vector<double> all = comm.allGather(std::vector<double>(mine.begin(), mine.end()));
  return std::set<int>(all.begin(), all.end());
}

void requireDistinctPoints(const DistributedLayout& layout, const std::vector<double>& overlapX,
                           const std::vector<double>& overlapVolume, double spacing, const std::string& inputFile) {
  const Communicator& comm = layout.comm();
  double smallest = 1e300;
  for (int i = 0; i < layout.numOwned(); ++i) smallest = std::min(smallest, overlapVolume[i]);
  const double tol = duplicateTolerance(spacing, -comm.max(-smallest));
  // The overlap points in gid order, so that the search's "smallest id" is the smallest gid.
  const std::vector<int>& gids = layout.gids();
  std::vector<int> order(gids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return gids[a] < gids[b]; });
  std::vector<double> x;
  x.reserve(overlapX.size());
  for (int k : order) x.insert(x.end(), &overlapX[3 * k], &overlapX[3 * k] + 3);
  const std::pair<int, int> d = findDuplicatePoints(x, tol);
  const double none = 1e300;  // ids as doubles, exact below 2^53
  const double i = d.first < 0 ? none : gids[order[d.first]], j = d.first < 0 ? none : gids[order[d.second]];
  const double iMin = -comm.max(-i);
  if (iMin == none) return;
  const double jMin = -comm.max(i == iMin ? -j : -none);
  const int root = comm.firstFailing(i == iMin && j == jMin);
  const std::string msg = comm.broadcast(
      i == iMin && j == jMin ? duplicateMessage(inputFile, static_cast<int>(i), static_cast<int>(j), &x[3 * d.first])
                             : std::string(),
      root);
  throw InputError(msg);
}

}  // namespace pf
