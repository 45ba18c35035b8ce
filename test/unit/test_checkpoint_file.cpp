// The checkpoint file format (output/CheckpointFile): numbers, bytes and copied files come back bit for bit;
// a truncated, padded, altered or foreign file is refused with a message naming it; a failed write leaves
// the previous checkpoint whole and no .tmp behind (the atomic rename).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "output/CheckpointFile.hpp"

namespace {

std::string dir() {
  static std::string d = [] {
    char tmpl[] = "/tmp/pf_checkpoint_file_XXXXXX";
    return std::string(mkdtemp(tmpl));
  }();
  return d;
}

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void spit(const std::string& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

pf::CheckpointData sample() {
  pf::CheckpointData d;
  d.numbers["node/Displacement"] = {1.0, -0.0, 1e-300, std::numeric_limits<double>::denorm_min(), -3.5e200,
                                    std::nextafter(1.0, 2.0)};
  d.numbers["empty"] = {};
  std::string binary = "a,b\n1,2\n";
  binary += std::string(1, '\0') + "\xff\x01";
  d.bytes["fingerprint/points"] = "2160";
  d.bytes["output/rs/csv"] = binary;
  return d;
}

// The message names the file and says why; the prefix is what the restart's one line shows.
void expectRefused(const std::string& path, const std::string& why) {
  try {
    pf::readCheckpoint(path);
    FAIL() << path << " was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'" + path + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(why), std::string::npos) << what;
  }
}

TEST(CheckpointFile, RoundTripIsBitExact) {
  const std::string path = dir() + "/round.restart", copied = dir() + "/copied.e";
  std::string big(3 << 20, '\0');  // more than one copy buffer
  for (std::size_t k = 0; k < big.size(); ++k) big[k] = static_cast<char>((k * 7919) % 251);
  spit(copied, big);
  pf::CheckpointData d = sample();
  d.fileCopies["output/rs/exodus"] = copied;
  pf::writeCheckpoint(path, d);
  EXPECT_FALSE(exists(path + ".tmp"));
  const pf::CheckpointData back = pf::readCheckpoint(path);
  ASSERT_EQ(back.numbers.size(), d.numbers.size());
  for (const auto& [name, values] : d.numbers) {
    const std::vector<double>& got = back.number(name);
    ASSERT_EQ(got.size(), values.size()) << name;
    for (std::size_t k = 0; k < values.size(); ++k) {
      EXPECT_EQ(std::signbit(got[k]), std::signbit(values[k])) << name << " " << k;  // -0.0 stays -0.0
      EXPECT_EQ(got[k], values[k]) << name << " " << k;
    }
  }
  EXPECT_EQ(back.text("fingerprint/points"), "2160");
  EXPECT_EQ(back.text("output/rs/csv"), d.bytes["output/rs/csv"]);
  EXPECT_EQ(back.text("output/rs/exodus"), big);
  EXPECT_THROW(back.number("no/such"), std::runtime_error);
}

TEST(CheckpointFile, RefusesTruncatedPaddedAlteredAndForeignFiles) {
  const std::string good = dir() + "/good.restart";
  pf::writeCheckpoint(good, sample());
  const std::string bytes = slurp(good);
  spit(dir() + "/half.restart", bytes.substr(0, bytes.size() / 2));
  expectRefused(dir() + "/half.restart", "truncated");
  spit(dir() + "/header.restart", bytes.substr(0, 30));  // inside the header
  expectRefused(dir() + "/header.restart", "truncated");
  spit(dir() + "/padded.restart", bytes + "x");
  expectRefused(dir() + "/padded.restart", "padded");
  for (std::size_t at : {bytes.size() - 1, bytes.size() / 2, std::size_t{40}}) {  // payload bytes
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    spit(dir() + "/flipped.restart", flipped);
    expectRefused(dir() + "/flipped.restart", "corrupt");
  }
  spit(dir() + "/deck.xml", "<ParameterList>\n</ParameterList>\n");
  expectRefused(dir() + "/deck.xml", "not a Periforge checkpoint");
  spit(dir() + "/empty.restart", "");
  expectRefused(dir() + "/empty.restart", "not a Periforge checkpoint");
  expectRefused(dir() + "/missing.restart", "cannot open");
}

TEST(CheckpointFile, AFailedWriteKeepsThePreviousCheckpoint) {
  const std::string path = dir() + "/keep.restart";
  pf::writeCheckpoint(path, sample());
  const std::string before = slurp(path);
  pf::CheckpointData d = sample();
  d.numbers["node/Displacement"] = {42.0};
  d.fileCopies["output/rs/exodus"] = dir() + "/no_such_part.e";  // fails half way through the payload
  EXPECT_THROW(pf::writeCheckpoint(path, d), std::runtime_error);
  EXPECT_EQ(slurp(path), before);
  EXPECT_FALSE(exists(path + ".tmp"));
  EXPECT_THROW(pf::writeCheckpoint(dir() + "/no_such_dir/x.restart", sample()), std::runtime_error);
}

}  // namespace
