// Agreeing on a failure that happened on one rank only (np = 2 under ctest): firstFailing, broadcast, and
// collectively(), which must make every rank throw the failing rank's error with its type, and never hang.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/InputError.hpp"
#include "parallel/Collective.hpp"
#include "parallel/Communicator.hpp"

namespace {

TEST(Communicator, FirstFailingIsTheLowestFailingRank) {
  const pf::Communicator world = pf::Communicator::world();
  EXPECT_EQ(world.firstFailing(false), -1);
  EXPECT_FALSE(world.anyFailed(false));
  EXPECT_EQ(world.firstFailing(true), 0);
  EXPECT_EQ(world.firstFailing(world.rank() == world.size() - 1), world.size() - 1);
  EXPECT_TRUE(world.anyFailed(world.rank() == world.size() - 1));
}

TEST(Communicator, BroadcastGivesEveryRankRootsText) {
  const pf::Communicator world = pf::Communicator::world();
  const int root = world.size() - 1;
  EXPECT_EQ(world.broadcast(world.rank() == root ? "from the last rank" : "ignored", root), "from the last rank");
  EXPECT_EQ(world.broadcast(world.rank() == 0 ? "" : "ignored", 0), "");
}

TEST(Collective, NoFailureNoThrow) {
  const pf::Communicator world = pf::Communicator::world();
  int calls = 0;
  EXPECT_NO_THROW(pf::collectively(world, [&] { ++calls; }));
  EXPECT_EQ(calls, 1);
}

TEST(Collective, RootOnlyFailureThrowsEverywhere) {
  const pf::Communicator world = pf::Communicator::world();
  try {
    pf::collectively(world, [&] {
      if (world.rank() == 0) throw std::runtime_error("disk full on rank 0");
    });
    FAIL() << "no exception on rank " << world.rank();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "disk full on rank 0");
  }
}

TEST(Collective, KeepsInputErrorTypeAndLowestRanksMessage) {
  const pf::Communicator world = pf::Communicator::world();
  EXPECT_THROW(pf::collectively(world, [&] {
                 if (world.rank() > 0) throw pf::InputError("rank " + std::to_string(world.rank()));
               }),
               pf::InputError);
  try {
    pf::collectively(world, [&] { throw pf::InputError("rank " + std::to_string(world.rank())); });
  } catch (const pf::InputError& e) {
    EXPECT_STREQ(e.what(), "rank 0");
  }
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
