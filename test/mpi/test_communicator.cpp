// Communicator on the ranks of the run (np = 2 under ctest): ranks, copies sharing one communicator, and
// reductions equal, bit for bit, to the sums and maxima of every rank's values written out here.
#include <gtest/gtest.h>

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "parallel/Communicator.hpp"

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Communicator, WorldRanks) {
  const pf::Communicator world = pf::Communicator::world();
  EXPECT_GE(world.rank(), 0);
  EXPECT_LT(world.rank(), world.size());
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  EXPECT_EQ(world.size(), size);
  const pf::Communicator copy = world;
  EXPECT_EQ(&copy.impl(), &world.impl());
  EXPECT_EQ(world.sum(1.0), static_cast<double>(world.size()));
  EXPECT_EQ(world.max(static_cast<double>(world.rank())), static_cast<double>(world.size() - 1));
  world.barrier();
}

// Rank r's values: sums that round, so a lost or doubled contribution shows in the last bits.
void valuesOf(int r, double* v) {
  v[0] = 0.1 * (r + 1);
  v[1] = 1e16 + 3 * r;
  v[2] = -1.0 / (r + 3);
  v[3] = 1e-300 * (r + 1);
}

TEST(Communicator, ReductionsAreEveryRanksSumAndMaximum) {
  const pf::Communicator world = pf::Communicator::world();
  double in[4], ours[4], sum[4] = {0, 0, 0, 0}, max[4], v[4];
  valuesOf(world.rank(), in);
  valuesOf(0, max);
  for (int r = 0; r < world.size(); ++r) {
    valuesOf(r, v);
    for (int k = 0; k < 4; ++k) sum[k] += v[k], max[k] = std::max(max[k], v[k]);
  }
  world.sum(in, ours, 4);
  // Two ranks (ctest): a + b has one rounding, whatever the order; more ranks may associate differently.
  for (int k = 0; k < 4; ++k)
    if (world.size() <= 2) EXPECT_TRUE(sameBits(ours[k], sum[k])) << "sum " << k;
    else EXPECT_NEAR(ours[k], sum[k], 1e-15 * std::fabs(sum[k])) << "sum " << k;
  world.max(in, ours, 4);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(sameBits(ours[k], max[k])) << "max " << k;
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
