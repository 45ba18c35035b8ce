// The Gmsh MSH 4.1 reader (input/GmshFile.hpp, discretization/GmshMesh.hpp) on meshes written here by hand: two
// hexahedra in two physical volumes (one named), a named physical surface and an unnamed physical point as node
// sets; the blocks, aliases, node-set names and members, a rank's share of the elements, a node block longer
// than the reader's chunk, and the errors of the physical groups (an entity in two groups, two unnamed groups
// of one tag, no groups at all) and of the format.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/InputError.hpp"
#include "discretization/GmshMesh.hpp"
#include "input/GmshFile.hpp"

namespace {

// Node id 1 + i + 3 j + 6 k at (i, j, k), i in 0..2, j, k in 0..1; hexahedron A is x in [0, 1], B x in [1, 2].
const char* kEntities =
    "$Entities\n1 0 1 2\n"
    "7 2 1 1 POINTPHYS\n"                    // point 7 at node 12, in the unnamed physical group 4
    "3 0 0 0 0 1 1 1 2 0\n"                  // surface 3 (x = 0), in physical group 2 "fixed"
    "1 0 0 0 1 1 1 VOL1 0\n"                 // volume 1, in physical group 5 "steel"
    "2 1 0 0 2 1 1 1 9 0\n"                  // volume 2, in physical group 9
    "$EndEntities\n";

// nodes: how many nodes the one node block holds (12 the mesh uses, the rest unused, for a long block).
std::string mesh(const std::string& version = "4.1", const std::string& vol1 = "1 5", const std::string& point = "1 4",
                 int nodes = 12) {
  std::ostringstream m;
  m.precision(17);
  m << "$MeshFormat\n" << version << " 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n3 5 \"steel\"\n2 2 \"fixed\"\n"
    << "$EndPhysicalNames\n";
  std::string e = kEntities;
  e.replace(e.find("VOL1"), 4, vol1);
  e.replace(e.find("POINTPHYS"), 9, point);
  m << e << "$Nodes\n1 " << nodes << " 1 " << nodes << "\n3 1 0 " << nodes << "\n";
  for (int t = 1; t <= nodes; ++t) m << t << "\n";
  for (int t = 1; t <= nodes; ++t) {
    const int i = (t - 1) % 3, j = (t - 1) / 3 % 2, k = (t - 1) / 6;
    m << i << " " << j << " " << k + (t > 12 ? 0.5 * t : 0.0) << "\n";  // unused nodes anywhere
  }
  m << "$EndNodes\n$Elements\n4 4 1 4\n3 1 5 1\n11 1 2 5 4 7 8 11 10\n3 2 5 1\n12 2 3 6 5 8 9 12 11\n"
    << "2 3 3 1\n13 1 4 10 7\n0 7 15 1\n14 12\n$EndElements\n";
  return m.str();
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& path) {
  try {
    pf::GmshFile f(path, "deck.xml");
  } catch (const pf::InputError& e) {
    return e.what();
  }
  return "";
}

pf::DiscretizationSpec spec(const std::string& path) {
  pf::DiscretizationSpec s;
  s.type = pf::DiscretizationSpec::Type::Gmsh;
  s.meshFile = path;
  return s;
}

TEST(GmshFile, BlocksAliasesAndNodeSets) {
  const pf::GmshFile f(write("two_hex.msh", mesh()), "deck.xml");
  const pf::GmshSummary& s = f.summary();
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.elements, 2);
  ASSERT_EQ(s.blocks.size(), 4u);
  EXPECT_EQ(s.blocks[0].block, 5);
  EXPECT_EQ(s.blocks[1].block, 9);
  EXPECT_EQ(s.blocks[1].first, 1);
  EXPECT_EQ(s.blocks[2].first, -1);  // the surface's elements carry a node set only
  ASSERT_EQ(s.blockNames.size(), 1u);
  EXPECT_EQ(s.blockNames[0], std::make_pair(std::string("steel"), 5));
  ASSERT_EQ(s.nodeSets.size(), 2u);
  EXPECT_EQ(s.nodeSets[0].name, "fixed");
  EXPECT_EQ(s.nodeSets[1].name, "nodelist_4");
}

TEST(GmshFile, PointsOfARanksShareAndNodeSetMembers) {
  const std::string path = write("two_hex_cloud.msh", mesh());
  const pf::PointCloud all = pf::readGmshSlab(spec(path), "deck.xml", 0, 1);
  ASSERT_EQ(all.size(), 2);
  EXPECT_DOUBLE_EQ(all.x[0], 0.5);
  EXPECT_DOUBLE_EQ(all.x[3], 1.5);
  EXPECT_DOUBLE_EQ(all.volume[1], 1.0);
  EXPECT_EQ(all.block, (std::vector<int>{5, 9}));
  EXPECT_EQ(all.generatedNodeSets.at("fixed"), std::vector<int>{0});       // the x = 0 face: element A
  EXPECT_EQ(all.generatedNodeSets.at("nodelist_4"), std::vector<int>{1});  // node 12: element B
  const pf::PointCloud second = pf::readGmshSlab(spec(path), "deck.xml", 1, 2);
  ASSERT_EQ(second.size(), 1);
  EXPECT_EQ(second.gid[0], 1);
  EXPECT_DOUBLE_EQ(second.x[0], 1.5);
  EXPECT_TRUE(second.generatedNodeSets.at("fixed").empty());
}

// 70 000 nodes in one block: forEachNode reads tags and coordinates in chunks of 2^16 from two positions.
TEST(GmshFile, ALongNodeBlockStreamsInChunks) {
  const int n = 70000;
  const pf::GmshFile f(write("long_block.msh", mesh("4.1", "1 5", "1 4", n)), "deck.xml");
  long long count = 0, tagsInOrder = 0;
  double lastZ = 0.0;
  f.forEachNode([&](long long tag, const double* x) {
    ++count;
    tagsInOrder += tag == count;
    if (tag == n) lastZ = x[2];
  });
  EXPECT_EQ(count, n);
  EXPECT_EQ(tagsInOrder, n);
  EXPECT_DOUBLE_EQ(lastZ, (n - 1) / 6 + 0.5 * n);
  const pf::PointCloud c = pf::readGmshSlab(spec(write("long_block_cloud.msh", mesh("4.1", "1 5", "1 4", n))),
                                            "deck.xml", 0, 1);
  EXPECT_DOUBLE_EQ(c.x[5], 0.5);
}

TEST(GmshFile, WithoutPhysicalVolumesTheBlockIsTheEntity) {
  std::string text = mesh("4.1", "0");
  text.replace(text.find("2 1 0 0 2 1 1 1 9 0"), 19, "2 1 0 0 2 1 1 0 0");
  const pf::GmshFile f(write("no_groups.msh", text), "deck.xml");
  EXPECT_EQ(f.summary().blocks[0].block, 1);
  EXPECT_EQ(f.summary().blocks[1].block, 2);
}

TEST(GmshFile, PhysicalGroupErrorsNameTheMesh) {
  const std::string two = errorOf(write("two_groups.msh", mesh("4.1", "2 5 9")));
  EXPECT_NE(two.find("volume 1 belong to 2 physical groups"), std::string::npos) << two;
  EXPECT_NE(two.find("two_groups.msh"), std::string::npos) << two;
  const std::string none = errorOf(write("one_ungrouped.msh", mesh("4.1", "0")));
  EXPECT_NE(none.find("volume 1 belong to 0 physical groups"), std::string::npos) << none;
  // Two unnamed groups of one tag in two lower dimensions (the surface's and the point's 4) collide.
  std::string clash = mesh();
  clash.replace(clash.find("3 0 0 0 0 1 1 1 2 0"), 19, "3 0 0 0 0 1 1 1 4 0");
  const std::string same = errorOf(write("clash.msh", clash));
  EXPECT_NE(same.find("node set name 'nodelist_4'"), std::string::npos) << same;
}

TEST(GmshFile, FormatErrors) {
  EXPECT_NE(errorOf(write("v22.msh", mesh("2.2"))).find("MSH version 2.2, Periforge reads MSH 4.1"), std::string::npos);
  EXPECT_NE(errorOf(write("text.msh", "0 0 0 1 1\n")).find("not a Gmsh MSH file"), std::string::npos);
  EXPECT_NE(errorOf(::testing::TempDir() + "absent.msh").find("cannot open the file"), std::string::npos);
  std::string cut = mesh();
  cut.resize(cut.find("12 2 3 6"));  // the file ends inside the elements
  EXPECT_NE(errorOf(write("cut.msh", cut)).find("the file ends"), std::string::npos) << errorOf(write("cut.msh", cut));
}

}  // namespace
