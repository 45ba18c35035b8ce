// OutputFiles: the lock (taken, refused while its owner lives, taken over from a dead one), the parts
// renamed on commit, the status line on abandon, and a directory in the way refused up front.
#include <gtest/gtest.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
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

// A live process named like this program (what a second periforge run looks like to the lock): a forked
// child renamed "periforge", waiting to be killed.
pid_t livePeriforge() {
  const pid_t child = fork();
  if (child == 0) {
    prctl(PR_SET_NAME, "periforge");
    for (;;) pause();
  }
  for (int i = 0; i < 200; ++i) {  // until the rename shows in /proc
    std::ifstream comm("/proc/" + std::to_string(child) + "/comm");
    std::string name;
    if (std::getline(comm, name) && name == "periforge") break;
    usleep(10000);
  }
  return child;
}

TEST(OutputFiles, LiveLockRefusesDeadLockIsTakenOver) {
  const std::string base = dir() + "/locked";
  const pid_t other = livePeriforge();
  write(base + ".lock", std::to_string(other) + "\n");  // a live run that is not this one
  try {
    pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
    FAIL() << "a live lock was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("deck.xml: Output/Output Filename"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("another run (pid "), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(base + ".lock"), std::to_string(other));
  kill(other, SIGKILL);
  waitpid(other, nullptr, 0);
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // reaped: its PID names no process now
  write(base + ".lock", std::to_string(child) + "\n");
  pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
  EXPECT_EQ(read(base + ".lock"), std::to_string(getpid()));
}

// Issue 40: a lock that holds no PID of a live run of this program is stale: garbage, an empty file (after
// the wait for a starting owner to write its PID), or the PID of a live process of another program.
TEST(OutputFiles, LockOfNoLiveRunIsTakenOver) {
  const std::string base = dir() + "/stale";
  for (const std::string content : {std::string("garbage\n"), std::string(""), std::to_string(getppid()) + "\n"}) {
    write(base + ".lock", content);
    pf::OutputFiles files(base, {".csv"}, "deck.xml: Output/Output Filename");
    EXPECT_EQ(read(base + ".lock"), std::to_string(getpid())) << "lock content '" << content << "'";
  }
}

TEST(OutputFiles, DirectoryInTheWayOrMissingIsRefused) {
  const std::string base = dir() + "/blocked";
  ASSERT_EQ(mkdir((base + ".e").c_str(), 0755), 0);
  EXPECT_THROW(pf::OutputFiles(base, {".csv", ".e"}, "w"), std::runtime_error);
  EXPECT_FALSE(exists(base + ".lock"));
  EXPECT_THROW(pf::OutputFiles(dir() + "/no_such_dir/x", {".csv"}, "w"), std::runtime_error);
}

}  // namespace
