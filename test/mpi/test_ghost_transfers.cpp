// GhostTransfers (Tpetra's since issue 20) under ctest at np 2 and np 3: for widths 1, 3 and 21 (a correspondence
// gather row) the import fills every ghost with its owner's values, the export adds every rank's copy into the
// owner (checked against the sum written out here), and the gather returns every point's values in cloud order on
// rank 0. (Before Epetra went, Tpetra's exports equalled Epetra's bit for bit here.)
#include <gtest/gtest.h>

#include <vector>

#include "parallel/Communicator.hpp"
#include "parallel/GhostTransfers.hpp"

namespace {

constexpr int kPoints = 47;

int owner(int g, int size) { return (g / 3 + g % 5) % size; }
// Rank r's ghosts: the points of other ranks with g % (r + 2) == 1 (uneven counts, every rank some).
bool ghostOf(int g, int r, int size) { return owner(g, size) != r && g % (r + 2) == 1; }
double value(int g, int c) { return 0.1 * g + 1e-3 * c + 1.0 / 3.0; }

struct Share {
  int numOwned = 0;
  std::vector<int> gids;  // owned (in descending order: not cloud order), then ghosts
};

Share share(const pf::Communicator& comm) {
  Share s;
  for (int g = kPoints - 1; g >= 0; --g)
    if (owner(g, comm.size()) == comm.rank()) s.gids.push_back(g);
  s.numOwned = static_cast<int>(s.gids.size());
  for (int g = 0; g < kPoints; ++g)
    if (ghostOf(g, comm.rank(), comm.size())) s.gids.push_back(g);
  return s;
}

TEST(GhostTransfers, EveryValueReachesWhereItBelongs) {
  const pf::Communicator comm = pf::Communicator::world();
  const Share s = share(comm);
  const auto transfers = pf::makeGhostTransfers(comm, s.numOwned, s.gids, kPoints);
  for (int w : {1, 3, 21}) {
    SCOPED_TRACE("width " + std::to_string(w));
    const std::size_t no = s.gids.size();
    std::vector<double> owned(static_cast<std::size_t>(w) * s.numOwned);
    for (int i = 0; i < s.numOwned; ++i)
      for (int c = 0; c < w; ++c) owned[w * i + c] = value(s.gids[i], c);
    {
      const pf::GhostTransfers* t = transfers.get();
      std::vector<double> overlap(w * no, -1.0);
      t->importToOverlap(owned.data(), overlap.data(), w);
      for (std::size_t i = 0; i < no; ++i)
        for (int c = 0; c < w; ++c) ASSERT_EQ(overlap[w * i + c], value(s.gids[i], c)) << "point " << s.gids[i];
      // Export: every copy of a point adds (c + 1) / (rank + 1); the owner gets the sum over the ranks holding it.
      for (std::size_t i = 0; i < no; ++i)
        for (int c = 0; c < w; ++c) overlap[w * i + c] = (c + 1.0) / (comm.rank() + 1.0);
      std::vector<double> sum(owned.size(), -1.0);
      t->exportAdd(overlap.data(), sum.data(), w);
      for (int i = 0; i < s.numOwned; ++i) {
        const int g = s.gids[i];
        for (int c = 0; c < w; ++c) {
          double expect = (c + 1.0) / (comm.rank() + 1.0);
          for (int r = 0; r < comm.size(); ++r)
            if (ghostOf(g, r, comm.size())) expect += (c + 1.0) / (r + 1.0);
          ASSERT_NEAR(sum[w * i + c], expect, 1e-15 * expect) << "point " << g;
        }
      }
      const std::vector<double> all = t->gatherToRoot(owned.data(), w);
      if (comm.rank() == 0) {
        ASSERT_EQ(all.size(), static_cast<std::size_t>(w) * kPoints);
        for (int g = 0; g < kPoints; ++g)
          for (int c = 0; c < w; ++c) ASSERT_EQ(all[w * g + c], value(g, c));
      } else {
        ASSERT_TRUE(all.empty());
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
