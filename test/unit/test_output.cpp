// Round trips for the output writers: what ExodusWriter puts in the file must be readable by
// the plain ExodusII API with Peridigm's layout, and HistoryWriter rows must parse back exactly.
#include <gtest/gtest.h>

#include <exodusII.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "output/ExodusWriter.hpp"
#include "output/HistoryWriter.hpp"

namespace {

std::string tempPath(const std::string& stem) {
  return ::testing::TempDir() + stem + "_" + std::to_string(::getpid());
}

std::vector<std::string> readNames(int exoid, ex_entity_type type, int n) {
  std::vector<std::vector<char>> storage(n, std::vector<char>(MAX_STR_LENGTH + 1, '\0'));
  std::vector<char*> ptrs;
  for (auto& s : storage) ptrs.push_back(s.data());
  EXPECT_GE(ex_get_variable_names(exoid, type, n, ptrs.data()), 0);
  std::vector<std::string> out;
  for (auto& s : storage) out.emplace_back(s.data());
  return out;
}

}  // namespace

TEST(ExodusWriter, RoundTripThreeNodesTwoSteps) {
  const std::string file = tempPath("pf_output_test") + ".e";
  // Node 1 in block 2, nodes 0 and 2 in block 1: checks the per-block element permutation.
  const std::vector<double> coords{0.0, 0.0, 0.0, 1.0, 0.5, 0.0, 2.0, 0.0, 0.25};
  const std::vector<int> blocks{1, 2, 1};
  {
    pf::ExodusWriter w(file, coords, blocks, false, {"Displacement"}, {"Damage"}, {"ID", "Dilatation"});
    for (int s = 0; s < 2; ++s) {
      std::map<std::string, std::vector<double>> vec, sca, ele;
      vec["Displacement"] = std::vector<double>(9);
      for (int i = 0; i < 9; ++i) vec["Displacement"][i] = 10.0 * s + i;
      sca["Damage"] = {0.1 * s, 0.2 * s, 0.3 * s};
      ele["ID"] = {1, 2, 3};
      ele["Dilatation"] = {-1.0 - s, -2.0 - s, -3.0 - s};
      ele["Unused"] = {7, 7, 7};  // extra entries are allowed
      w.writeStep(0.5 * s, vec, sca, ele);
    }
    EXPECT_EQ(w.numStepsWritten(), 2);
  }

  int cpu = sizeof(double), io = 0;
  float version = 0;
  int exoid = ex_open(file.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(exoid, 0);
  char title[MAX_LINE_LENGTH + 1] = {0};
  int ndim = 0, nnodes = 0, nelem = 0, nblk = 0, nns = 0, nss = 0;
  ASSERT_GE(ex_get_init(exoid, title, &ndim, &nnodes, &nelem, &nblk, &nns, &nss), 0);
  EXPECT_EQ(ndim, 3);
  EXPECT_EQ(nnodes, 3);
  EXPECT_EQ(nelem, 3);
  EXPECT_EQ(nblk, 2);
  EXPECT_EQ(nns, 0);

  std::vector<double> x(3), y(3), z(3);
  ASSERT_GE(ex_get_coord(exoid, x.data(), y.data(), z.data()), 0);
  for (int n = 0; n < 3; ++n) {
    EXPECT_DOUBLE_EQ(x[n], coords[3 * n]);
    EXPECT_DOUBLE_EQ(y[n], coords[3 * n + 1]);
    EXPECT_DOUBLE_EQ(z[n], coords[3 * n + 2]);
  }

  std::vector<int> ids(2);
  ASSERT_GE(ex_get_ids(exoid, EX_ELEM_BLOCK, ids.data()), 0);
  EXPECT_EQ(ids, (std::vector<int>{1, 2}));
  char etype[MAX_STR_LENGTH + 1] = {0};
  int nInBlk = 0, nPerEl = 0, nEdge = 0, nFace = 0, nAttr = 0;
  ASSERT_GE(ex_get_block(exoid, EX_ELEM_BLOCK, 1, etype, &nInBlk, &nPerEl, &nEdge, &nFace, &nAttr), 0);
  EXPECT_STREQ(etype, "SPHERE");
  EXPECT_EQ(nInBlk, 2);
  EXPECT_EQ(nPerEl, 1);
  std::vector<int> conn(2);
  ASSERT_GE(ex_get_conn(exoid, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr), 0);
  EXPECT_EQ(conn, (std::vector<int>{1, 3}));
  std::vector<int> elemMap(3);
  ASSERT_GE(ex_get_id_map(exoid, EX_ELEM_MAP, elemMap.data()), 0);
  EXPECT_EQ(elemMap, (std::vector<int>{1, 3, 2}));

  int nNodVar = 0, nElVar = 0;
  ASSERT_GE(ex_get_variable_param(exoid, EX_NODAL, &nNodVar), 0);
  ASSERT_GE(ex_get_variable_param(exoid, EX_ELEM_BLOCK, &nElVar), 0);
  EXPECT_EQ(readNames(exoid, EX_NODAL, nNodVar),
            (std::vector<std::string>{"DisplacementX", "DisplacementY", "DisplacementZ", "Damage"}));
  EXPECT_EQ(readNames(exoid, EX_ELEM_BLOCK, nElVar), (std::vector<std::string>{"ID", "Dilatation"}));

  ASSERT_EQ(ex_inquire_int(exoid, EX_INQ_TIME), 2);
  for (int s = 0; s < 2; ++s) {
    double t = -1;
    ASSERT_GE(ex_get_time(exoid, s + 1, &t), 0);
    EXPECT_DOUBLE_EQ(t, 0.5 * s);
    std::vector<double> v(3);
    ASSERT_GE(ex_get_var(exoid, s + 1, EX_NODAL, 2, 1, 3, v.data()), 0);  // DisplacementY
    for (int n = 0; n < 3; ++n) EXPECT_DOUBLE_EQ(v[n], 10.0 * s + 3 * n + 1);
    ASSERT_GE(ex_get_var(exoid, s + 1, EX_NODAL, 4, 1, 3, v.data()), 0);  // Damage
    EXPECT_DOUBLE_EQ(v[2], 0.3 * s);
    std::vector<double> e1(2), e2(1);
    ASSERT_GE(ex_get_var(exoid, s + 1, EX_ELEM_BLOCK, 2, 1, 2, e1.data()), 0);
    ASSERT_GE(ex_get_var(exoid, s + 1, EX_ELEM_BLOCK, 2, 2, 1, e2.data()), 0);
    EXPECT_DOUBLE_EQ(e1[0], -1.0 - s);
    EXPECT_DOUBLE_EQ(e1[1], -3.0 - s);
    EXPECT_DOUBLE_EQ(e2[0], -2.0 - s);
  }
  ex_close(exoid);
  std::remove(file.c_str());
}

TEST(ExodusWriter, PlanarZeroesZComponent) {
  const std::string file = tempPath("pf_output_planar") + ".e";
  {
    pf::ExodusWriter w(file, {0, 0, 0, 1, 0, 0}, {1, 1}, true, {"Displacement"}, {}, {});
    w.writeStep(0.0, {{"Displacement", {1, 2, 3, 4, 5, 6}}}, {}, {});
  }
  int cpu = sizeof(double), io = 0;
  float version = 0;
  int exoid = ex_open(file.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(exoid, 0);
  std::vector<double> v(2);
  ASSERT_GE(ex_get_var(exoid, 1, EX_NODAL, 3, 1, 2, v.data()), 0);
  EXPECT_EQ(v, (std::vector<double>{0.0, 0.0}));
  ex_close(exoid);
  std::remove(file.c_str());
}

TEST(ExodusWriter, ErrorsNameTheFile) {
  const std::string bad = "/nonexistent_dir_pf/out.e";
  try {
    pf::ExodusWriter w(bad, {0, 0, 0}, {1}, false, {}, {}, {});
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
  const std::string file = tempPath("pf_output_err") + ".e";
  pf::ExodusWriter w(file, {0, 0, 0}, {1}, false, {"Velocity"}, {}, {"Dilatation"});
  EXPECT_THROW(w.writeStep(0.0, {}, {}, {{"Dilatation", {0.0}}}), std::runtime_error);
  EXPECT_THROW(w.writeStep(0.0, {{"Velocity", {1, 2}}}, {}, {{"Dilatation", {0.0}}}), std::runtime_error);
  EXPECT_EQ(w.numStepsWritten(), 0);
  EXPECT_THROW(pf::ExodusWriter(file + "2", {0, 0, 0}, {1}, false, {}, {std::string(40, 'a')}, {}),
               std::runtime_error);
  std::remove(file.c_str());
  std::remove((file + "2").c_str());
}

TEST(HistoryWriter, RoundTrip) {
  const std::string file = tempPath("pf_history") + ".csv";
  const std::vector<double> row1{0.0, 1.0 / 3.0, -2.5e-300};
  const std::vector<double> row2{1.0, 0.1, 6.02214076e23};
  {
    pf::HistoryWriter h(file, {"Time", "Applied_Displacement", "Reaction_Left_X"});
    h.writeRow(row1);
    // Flushed per row: another reader sees it before the writer is closed.
    std::ifstream early(file);
    std::string l1, l2;
    std::getline(early, l1);
    std::getline(early, l2);
    EXPECT_FALSE(l2.empty());
    h.writeRow(row2);
    EXPECT_THROW(h.writeRow({1.0}), std::runtime_error);
  }
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "Time,Applied_Displacement,Reaction_Left_X");
  for (const auto& expected : {row1, row2}) {
    ASSERT_TRUE(std::getline(in, line));
    std::stringstream ss(line);
    std::string cell;
    std::size_t i = 0;
    while (std::getline(ss, cell, ',')) {
      ASSERT_LT(i, expected.size());
      EXPECT_EQ(std::stod(cell), expected[i]) << "column " << i;  // exact: %.17g round-trips
      ++i;
    }
    EXPECT_EQ(i, expected.size());
  }
  EXPECT_FALSE(std::getline(in, line));
  std::remove(file.c_str());
}

TEST(HistoryWriter, Errors) {
  EXPECT_THROW(pf::HistoryWriter("/nonexistent_dir_pf/h.csv", {"a"}), std::runtime_error);
  const std::string file = tempPath("pf_history_err") + ".csv";
  EXPECT_THROW(pf::HistoryWriter(file, {"a", "a"}), std::runtime_error);
  EXPECT_THROW(pf::HistoryWriter(file, {"a,b"}), std::runtime_error);
  std::remove(file.c_str());
}
