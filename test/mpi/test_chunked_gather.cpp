// ChunkedGather under ctest at np = 2 and np = 3: a chunk size far below the points per rank (several chunks),
// uneven ownership in scrambled local order, ranks owning no point of some chunks; the Exodus file written
// chunk by chunk (its element blocks from block ids given a chunk at a time) must equal, byte for byte, the
// one written from whole fields. The variable-width gather and
// both scatters (checkpoints' direction to and from rank 0) carry every value to its point, zero widths
// included, and a failing reader or putter ends the exchange on every rank without a hang.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <algorithm>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

#include "output/ExodusWriter.hpp"
#include "parallel/ChunkedGather.hpp"
#include "parallel/Communicator.hpp"

namespace {

constexpr int kPoints = 61;  // 9 chunks of 7, the last one of 5
constexpr int kChunk = 7;

// Rank 0 owns all of [0, 14) (chunks 0 and 1 come from it alone), then an uneven, irregular split.
int owner(int g, int size) {
  if (g < 14) return 0;
  if (g % 11 == 0) return size - 1;
  return (g / 5 + g % 3) % size;
}

double value(int g, int c, int step) { return 1000.0 * step + 10.0 * g + c + 0.125; }

struct Share {
  std::vector<int> gids;  // owned, in descending cloud order (the gather must sort)
  std::vector<double> vec, scalar;
  std::vector<pf::ChunkedGather::Field> fields() const {
    return {{[this](int i, double* out) { std::copy_n(vec.data() + 3 * i, 3, out); }, 3},
            {[this](int i, double* out) { *out = scalar[i]; }, 1}};
  }
};

Share share(const pf::Communicator& comm, int step) {
  Share s;
  for (int g = kPoints - 1; g >= 0; --g)
    if (owner(g, comm.size()) == comm.rank()) {
      s.gids.push_back(g);
      for (int c = 0; c < 3; ++c) s.vec.push_back(value(g, c, step));
      s.scalar.push_back(-value(g, 7, step));
    }
  return s;
}

std::vector<double> coords() {
  std::vector<double> x;
  for (int g = 0; g < kPoints; ++g)
    for (double c : {0.5 * g, 1.0 - g, 0.25 * g * g}) x.push_back(c);
  return x;
}

// Two blocks in interleaved runs of 6, so runs cross chunk boundaries.
std::vector<int> blocks() {
  std::vector<int> b;
  for (int g = 0; g < kPoints; ++g) b.push_back(1 + (g / 6) % 2);
  return b;
}

std::string bytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ChunkedGather, ChunksArriveInOrderWithEveryValue) {
  const pf::Communicator comm = pf::Communicator::world();
  ASSERT_GE(comm.size(), 2);
  const Share s = share(comm, 1);
  EXPECT_GT(static_cast<int>(s.gids.size()), kChunk) << "several chunks per rank";
  pf::ChunkedGather gather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk);
  EXPECT_EQ(gather.numChunks(), 9);
  for (int pass = 0; pass < 2; ++pass) {  // the pattern is reused
    int next = 0, calls = 0;
    gather.gather(s.fields(),
                  [&](int begin, int count, const std::vector<const double*>& v) {
                    EXPECT_EQ(comm.rank(), 0);
                    EXPECT_EQ(begin, next);
                    EXPECT_EQ(count, std::min(kChunk, kPoints - begin));
                    ASSERT_EQ(v.size(), 2u);
                    for (int i = 0; i < count; ++i) {
                      for (int c = 0; c < 3; ++c) EXPECT_EQ(v[0][3 * i + c], value(begin + i, c, 1));
                      EXPECT_EQ(v[1][i], -value(begin + i, 7, 1));
                    }
                    next += count;
                    ++calls;
                  });
    EXPECT_EQ(calls, comm.rank() == 0 ? 9 : 0);
    if (comm.rank() == 0) {
      EXPECT_EQ(next, kPoints);
    }
  }
}

TEST(ChunkedGather, ChunkedExodusEqualsWholeFieldExodus) {
  const pf::Communicator comm = pf::Communicator::world();
  const std::string base = "chunked_gather_np" + std::to_string(comm.size());
  const Share first = share(comm, 0);
  pf::ChunkedGather gather(comm, first.gids.data(), static_cast<int>(first.gids.size()), kPoints, kChunk);
  std::unique_ptr<pf::ExodusWriter> chunked, whole;
  if (comm.rank() == 0) {
    pf::BlockRuns runs;  // the block ids a chunk at a time, runs crossing the chunk boundaries
    const std::vector<int> ids = blocks();
    for (int begin = 0; begin < kPoints; begin += kChunk)
      runs.add(ids.data() + begin, static_cast<std::size_t>(std::min(kChunk, kPoints - begin)));
    EXPECT_EQ(runs.runs().size(), 11u);  // 61 points in runs of 6
    chunked = std::make_unique<pf::ExodusWriter>(base + "_chunked.e", coords(), runs, false,
                                                 std::vector<std::string>{"Displacement"}, std::vector<std::string>{},
                                                 std::vector<std::string>{"Damage"}, std::vector<std::string>{"E"});
    whole = std::make_unique<pf::ExodusWriter>(base + "_whole.e", coords(), blocks(), false,
                                               std::vector<std::string>{"Displacement"}, std::vector<std::string>{},
                                               std::vector<std::string>{"Damage"}, std::vector<std::string>{"E"});
  }
  for (int step = 0; step < 3; ++step) {
    const Share s = share(comm, step);
    const std::map<std::string, double> globals{{"E", 0.5 * step}};
    gather.gather(s.fields(),
                  [&](int begin, int count, const std::vector<const double*>& v) {
                    if (begin == 0) chunked->beginStep(0.1 * step);
                    chunked->writeNodes(begin, count, {v[0]}, {}, {v[1]});
                    if (begin + count == kPoints) chunked->endStep(globals);
                  });
    if (comm.rank() != 0) continue;
    std::map<std::string, std::vector<double>> vec, scalar;
    for (int g = 0; g < kPoints; ++g) {
      for (int c = 0; c < 3; ++c) vec["Displacement"].push_back(value(g, c, step));
      scalar["Damage"].push_back(-value(g, 7, step));
    }
    whole->writeStep(0.1 * step, vec, {}, scalar, globals);
  }
  if (comm.rank() == 0) {
    chunked.reset();
    whole.reset();
    const std::string a = bytes(base + "_chunked.e"), b = bytes(base + "_whole.e");
    EXPECT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == b) << "chunked and whole-field files differ";
    std::remove((base + "_chunked.e").c_str());
    std::remove((base + "_whole.e").c_str());
  }
}

TEST(ChunkedGather, WriterFailureEndsOnEveryRank) {
  const pf::Communicator comm = pf::Communicator::world();
  const Share s = share(comm, 0);
  pf::ChunkedGather gather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk);
  int calls = 0;
  auto run = [&] {
    gather.gather({s.fields()[1]}, [&](int begin, int, const std::vector<const double*>&) {
      ++calls;
      if (begin == 2 * kChunk) throw std::runtime_error("disk full");
    });
  };
  if (comm.rank() == 0)
    EXPECT_THROW(run(), std::runtime_error);
  else
    EXPECT_NO_THROW(run());
  EXPECT_EQ(calls, comm.rank() == 0 ? 3 : 0);  // no write after the failure
  EXPECT_EQ(comm.sum(1.0), comm.size());      // and no rank is left waiting
}

TEST(ChunkedGather, OwnershipThatMissesAPointFailsOnEveryRank) {
  const pf::Communicator comm = pf::Communicator::world();
  Share s = share(comm, 0);
  if (comm.rank() == 0) s.gids.pop_back();  // drops cloud index 0
  EXPECT_THROW(pf::ChunkedGather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk),
               std::logic_error);
}

int width(int g) { return g % 5; }  // 0 to 4 values per point: some points have none
double bondValue(int g, int j) { return 100.0 * g + j + 0.5; }

TEST(ChunkedGather, VariableWidthsGatherInCloudOrder) {
  const pf::Communicator comm = pf::Communicator::world();
  const Share s = share(comm, 0);
  pf::ChunkedGather gather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk);
  const pf::ChunkedGather::VariableField field{
      [&](int i) { return width(s.gids[i]); },
      [&](int i, double* out) {
        for (int j = 0; j < width(s.gids[i]); ++j) out[j] = bondValue(s.gids[i], j);
      }};
  int next = 0;
  gather.gatherVariable(field, [&](int begin, int count, const double* values, std::size_t n) {
    EXPECT_EQ(begin, next);
    std::vector<double> expected;
    for (int g = begin; g < begin + count; ++g)
      for (int j = 0; j < width(g); ++j) expected.push_back(bondValue(g, j));
    ASSERT_EQ(n, expected.size());
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), values));
    next += count;
  });
  EXPECT_EQ(next, comm.rank() == 0 ? kPoints : 0);
}

TEST(ChunkedGather, ScattersReachTheOwnersOnly) {
  const pf::Communicator comm = pf::Communicator::world();
  const Share s = share(comm, 0);
  pf::ChunkedGather gather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk);
  std::vector<int> seen(s.gids.size(), 0);
  int reads = 0;
  gather.scatter(
      3,
      [&](int begin, int count, double* out) {
        ++reads;
        for (int g = begin; g < begin + count; ++g)
          for (int c = 0; c < 3; ++c) *out++ = value(g, c, 5);
      },
      [&](int i, const double* in) {
        ++seen[i];
        for (int c = 0; c < 3; ++c) EXPECT_EQ(in[c], value(s.gids[i], c, 5)) << s.gids[i];
      });
  EXPECT_EQ(reads, comm.rank() == 0 ? 9 : 0);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  std::fill(seen.begin(), seen.end(), 0);
  gather.scatterVariable(
      2,
      [&](int begin, int count, std::vector<double>& msg) {
        for (int g = begin; g < begin + count; ++g) msg.push_back(width(g));
        for (int sign : {1, -1})
          for (int g = begin; g < begin + count; ++g)
            for (int j = 0; j < width(g); ++j) msg.push_back(sign * bondValue(g, j));
      },
      [&](int i, int w, const std::vector<const double*>& blocks) {
        ++seen[i];
        const int g = s.gids[i];
        ASSERT_EQ(w, width(g));
        for (int j = 0; j < w; ++j) {
          EXPECT_EQ(blocks[0][j], bondValue(g, j));
          EXPECT_EQ(blocks[1][j], -bondValue(g, j));
        }
      });
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(ChunkedGather, AFailingScatterEndsOnEveryRank) {
  const pf::Communicator comm = pf::Communicator::world();
  const Share s = share(comm, 0);
  pf::ChunkedGather gather(comm, s.gids.data(), static_cast<int>(s.gids.size()), kPoints, kChunk);
  int reads = 0;
  auto readFails = [&] {
    gather.scatter(
        1,
        [&](int begin, int, double*) {
          ++reads;
          if (begin == 2 * kChunk) throw std::runtime_error("short file");
        },
        [](int, const double*) {});
  };
  if (comm.rank() == 0)
    EXPECT_THROW(readFails(), std::runtime_error);
  else
    EXPECT_NO_THROW(readFails());
  EXPECT_EQ(reads, comm.rank() == 0 ? 3 : 0);  // no read after the failure
  auto putFails = [&] {  // the last rank refuses its first point, the others take theirs
    gather.scatterVariable(
        1, [](int, int count, std::vector<double>& msg) { msg.assign(static_cast<std::size_t>(count), 0.0); },
        [&](int, int, const std::vector<const double*>&) {
          if (comm.rank() == comm.size() - 1) throw std::runtime_error("bond count differs");
        });
  };
  if (comm.rank() == comm.size() - 1)
    EXPECT_THROW(putFails(), std::runtime_error);
  else
    EXPECT_NO_THROW(putFails());
  EXPECT_EQ(comm.sum(1.0), comm.size());  // no rank is left waiting
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
