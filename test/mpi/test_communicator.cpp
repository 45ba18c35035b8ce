// Communicator on the ranks of the run (np = 2 under ctest): ranks, copies sharing one communicator,
// and reductions bit-identical to Epetra's SumAll/MaxAll, which the solvers and writers used before.
#include <gtest/gtest.h>

#include <cstring>

#include "parallel/Communicator.hpp"
#include "parallel/CommunicatorImpl.hpp"

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Communicator, WorldRanks) {
  const pf::Communicator world = pf::Communicator::world();
  EXPECT_GE(world.rank(), 0);
  EXPECT_LT(world.rank(), world.size());
  EXPECT_EQ(world.size(), world.impl().epetra.NumProc());
  const pf::Communicator copy = world;
  EXPECT_EQ(&copy.impl(), &world.impl());
  EXPECT_EQ(world.sum(1.0), static_cast<double>(world.size()));
  EXPECT_EQ(world.max(static_cast<double>(world.rank())), static_cast<double>(world.size() - 1));
  world.barrier();
}

TEST(Communicator, ReductionsMatchEpetra) {
  const pf::Communicator world = pf::Communicator::world();
  const double r = world.rank();
  // Values whose sum rounds: any other reduction order or algorithm would show in the last bits.
  double in[4] = {0.1 * (r + 1), 1e16 + 3 * r, -1.0 / (r + 3), 1e-300 * (r + 1)};
  double ours[4], theirs[4];
  world.sum(in, ours, 4);
  world.impl().epetra.SumAll(in, theirs, 4);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(sameBits(ours[k], theirs[k])) << "sum " << k;
  world.max(in, ours, 4);
  world.impl().epetra.MaxAll(in, theirs, 4);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(sameBits(ours[k], theirs[k])) << "max " << k;
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
