// OutputFiles: the lock (taken, refused while its owner lives, taken over from a dead one), the parts
// renamed on commit, the status line on abandon, and a directory in the way refused up front.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "output/OutputFiles.hpp"

namespace {

std::string dir() {
  static std::string d = [] {
    char tmpl[] = "/tmp/pf_output_files_XXXXXX";
    return std::string(mkdtemp(tmpl));
  }();
  return d;
}

bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

std::string read(const std::string& p) {
  std::ifstream in(p);
  std::string s;
  std::getline(in, s);
  return s;
}

void write(const std::string& p, const std::string& text) { std::ofstream(p) << text; }

TEST(OutputFiles, CommitRenamesPartsAndReleasesTheLock) {
  const std::string base = dir() + "/ok";
  write(base + ".csv", "old");
  write(base + ".status", "failed after step 1: old");
  {
    pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
    EXPECT_TRUE(exists(base + ".lock"));
    EXPECT_EQ(read(base + ".status").rfind("running (pid ", 0), 0u);
    write(files.part(".csv"), "new");
    EXPECT_EQ(read(base + ".csv"), "old");
    files.commit();
  }
  EXPECT_EQ(read(base + ".csv"), "new");
  EXPECT_FALSE(exists(base + ".csv.part"));
  EXPECT_FALSE(exists(base + ".status"));
  EXPECT_FALSE(exists(base + ".lock"));
}

TEST(OutputFiles, AbandonKeepsTheResultAndWritesTheStatus) {
  const std::string base = dir() + "/failed";
  write(base + ".csv", "good");
  {
    pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
    write(files.part(".csv"), "partial");
    files.abandon("failed after step 3 (t = 0.3): solver failed");
  }
  EXPECT_EQ(read(base + ".csv"), "good");
  EXPECT_EQ(read(base + ".csv.part"), "partial");
  EXPECT_EQ(read(base + ".status"), "failed after step 3 (t = 0.3): solver failed");
  EXPECT_FALSE(exists(base + ".lock"));
}

TEST(OutputFiles, LiveLockRefusesDeadLockIsTakenOver) {
  const std::string base = dir() + "/locked";
  write(base + ".lock", std::to_string(getppid()) + "\n");  // a live process that is not this one
  try {
    pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
    FAIL() << "a live lock was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("deck.xml: Output/Output Filename"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("another run (pid "), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(base + ".lock"), std::to_string(getppid()));
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // reaped: its PID names no process now
  write(base + ".lock", std::to_string(child) + "\n");
  pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
  EXPECT_EQ(read(base + ".lock"), std::to_string(getpid()));
}

TEST(OutputFiles, DirectoryInTheWayOrMissingIsRefused) {
  const std::string base = dir() + "/blocked";
  ASSERT_EQ(mkdir((base + ".e").c_str(), 0755), 0);
  EXPECT_THROW(pf::OutputFiles(base, {".csv", ".e"}, "w"), std::runtime_error);
  EXPECT_FALSE(exists(base + ".lock"));
  EXPECT_THROW(pf::OutputFiles(dir() + "/no_such_dir/x", {".csv"}, "w"), std::runtime_error);
}

}  // namespace
