// Discretizations (PdQuickGrid, Text File, Periforge generators) and node sets.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "discretization/Discretization.hpp"
#include "core/InfluenceFunction.hpp"
#include "input/InputSchema.hpp"
#include "input/ListReader.hpp"
#include "discretization/NodeSets.hpp"
#include "test_input_helpers.hpp"

using Teuchos::ParameterList;

namespace {

const char* kFile = "deck.xml";

ParameterList quickGrid(int nx, int ny, int nz) {
  ParameterList d;
  d.set("Type", std::string("PdQuickGrid"));
  d.set("NeighborhoodType", std::string("Spherical"));
  ParameterList& g = d.sublist("TensorProduct3DMeshGenerator");
  g.set("Type", std::string("PdQuickGrid"));
  g.set("X Origin", -1.5);
  g.set("Y Origin", -1.0);
  g.set("Z Origin", -1.0);
  g.set("X Length", 3.0);
  g.set("Y Length", 2.0);
  g.set("Z Length", 4.0);
  g.set("Number Points X", nx);
  g.set("Number Points Y", ny);
  g.set("Number Points Z", nz);
  return d;
}

// The plate of the paper: 100 x 100 x 1 mm, hole of diameter 30 mm at the centre, spacing 0.25 mm,
// fictitious layers on the loaded faces.
ParameterList plate(const std::string& grid, double layerWidth) {
  ParameterList d;
  d.set("Type", std::string("Rectangle With Holes"));
  d.set("X Origin", -50.0);
  d.set("Y Origin", -50.0);
  d.set("X Length", 100.0);
  d.set("Y Length", 100.0);
  d.set("Spacing", 0.25);
  d.set("Thickness", 1.0);
  d.set("Grid", grid);
  d.set("Fictitious Layers", std::string("Bottom Top"));
  if (layerWidth > 0) d.set("Layer Width", layerWidth);
  ParameterList& h = d.sublist("Holes").sublist("Centre Hole");
  h.set("X Center", 0.0);
  h.set("Y Center", 0.0);
  h.set("Radius", 15.0);
  return d;
}

// A 4 x 4 x 2 box of unit cells with layers on two faces and a bore of radius 1 along z through its centre.
ParameterList boxWithBore() {
  ParameterList d;
  d.set("Type", std::string("Box With Holes"));
  d.set("X Length", 4.0);
  d.set("Y Length", 4.0);
  d.set("Z Length", 2.0);
  d.set("Spacing", 1.0);
  d.set("Fictitious Layers", std::string("Left Front"));
  d.set("Layer Width", 2.0);
  ParameterList& h = d.sublist("Holes").sublist("Bore");
  h.set("X Center", 2.0);
  h.set("Y Center", 2.0);
  h.set("Z Center", 0.0);
  h.set("Radius", 1.0);
  h.set("Axis", std::string("0 0 1"));
  return d;
}

}  // namespace

TEST(Discretization, QuickGridOrderAndVolumes) {
  const pf::PointCloud c = pftest::cloudOf(quickGrid(3, 2, 2), kFile, ".");
  ASSERT_EQ(c.size(), 12);
  // x fastest, then y, then z; points at cell centres.
  EXPECT_DOUBLE_EQ(c.x[0], -1.0);
  EXPECT_DOUBLE_EQ(c.x[1], -0.5);
  EXPECT_DOUBLE_EQ(c.x[2], 0.0);
  EXPECT_DOUBLE_EQ(c.x[3 * 1 + 0], 0.0);
  EXPECT_DOUBLE_EQ(c.x[3 * 3 + 1], 0.5);
  EXPECT_DOUBLE_EQ(c.x[3 * 6 + 2], 2.0);
  for (int i = 0; i < c.size(); ++i) {
    EXPECT_DOUBLE_EQ(c.volume[i], 1.0 * 1.0 * 2.0);
    EXPECT_EQ(c.block[i], 1);
  }
  EXPECT_EQ(c.spacing, 0.0);  // dz differs
  EXPECT_FALSE(c.planar);
  EXPECT_EQ(c.influence, pf::Influence::One);
}

TEST(Discretization, UserDefinedInfluenceFunctionAsPeridigm) {
  // Peridigm compiles any other string as an expression in zeta (bond length) and horizon.
  const pf::Influence f = pf::influenceFromName("1.0/zeta", kFile);
  EXPECT_EQ(f, pf::Influence::UserDefined);
  EXPECT_DOUBLE_EQ(pf::influenceValue(f, 2.0, 3.0), 0.5);
  const pf::Influence g = pf::influenceFromName("if (zeta < 0.5*horizon) { value = 1.0; } else { value = 0.25; }", kFile);
  EXPECT_DOUBLE_EQ(pf::influenceValue(g, 1.0, 3.0), 1.0);
  EXPECT_DOUBLE_EQ(pf::influenceValue(g, 2.0, 3.0), 0.25);
  EXPECT_INPUT_ERROR(pf::influenceFromName("1.0/(zeta", kFile), kFile, "Influence Function");
}

TEST(Discretization, InfluenceFunctionsMatchPeridigm) {
  ParameterList d = quickGrid(1, 1, 1);
  d.set("Influence Function", std::string("Parabolic Decay"));
  const pf::PointCloud c = pftest::cloudOf(d, kFile, ".");
  EXPECT_EQ(c.influence, pf::Influence::ParabolicDecay);
  EXPECT_DOUBLE_EQ(pf::influenceValue(pf::Influence::ParabolicDecay, 0.4, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(pf::influenceValue(pf::Influence::ParabolicDecay, 0.5, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(pf::influenceValue(pf::Influence::ParabolicDecay, 0.75, 1.0), 0.75);
  EXPECT_DOUBLE_EQ(pf::influenceValue(pf::Influence::ParabolicDecay, 1.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pf::influenceValue(pf::Influence::Gaussian, 1.0, 2.0), std::exp(-0.25));
  d.set("Influence Function", std::string("Cubic"));
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, "."), kFile, "Influence Function");
}

TEST(Discretization, TextFileParsesAndRejectsBadLines) {
  const std::string mesh = pftest::writeTemp("pf_mesh.txt",
                                             "# x y z block_id volume\n"
                                             "0 0 0 1 0.5\n"
                                             "\n"
                                             "1.0 0 0 2 0.25  # trailing comment\n");
  ParameterList d;
  d.set("Type", std::string("Text File"));
  d.set("Input Mesh File", std::string("pf_mesh.txt"));
  const std::string dir = ::testing::TempDir();
  const pf::PointCloud c = pftest::cloudOf(d, kFile, dir);
  ASSERT_EQ(c.size(), 2);
  EXPECT_EQ(c.block[1], 2);
  EXPECT_DOUBLE_EQ(c.volume[1], 0.25);
  EXPECT_DOUBLE_EQ(c.x[3], 1.0);

  pftest::writeTemp("pf_badmesh.txt", "0 0 0 1 0.5\n0 0 1 0.5\n");
  d.set("Input Mesh File", std::string("pf_badmesh.txt"));
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, dir), kFile, "pf_badmesh.txt:2:");
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, dir), kFile, "Input Mesh File");

  d.set("Input Mesh File", std::string("no_such_mesh.txt"));
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, dir), kFile, "no_such_mesh.txt");

  // Found by the fuzz test: a NUL byte cut the message short; a block id past an int wrapped into another.
  pftest::writeTemp("pf_nulmesh.txt", std::string("0 0 0 1 0.5\n1 0 0 1 0.5") + '\0' + "\n");
  d.set("Input Mesh File", std::string("pf_nulmesh.txt"));
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, dir), kFile, "got '1 0 0 1 0.5\\x00'");
  pftest::writeTemp("pf_bigblock.txt", "0 0 0 99999999999 0.5\n");
  d.set("Input Mesh File", std::string("pf_bigblock.txt"));
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, dir), kFile, "up to 2147483647 (got 99999999999)");
}

// A rank builds only its slab: the slabs of any part count are the whole cloud's points, gids and generated
// node sets, cut in order at N*part/parts.
TEST(Discretization, SlabsAreTheWholeCloudInPieces) {
  ParameterList d = boxWithBore();
  const pf::DiscretizationSpec spec = pf::parseDiscretization(d, kFile, ".");
  const pf::PointCloud whole = pf::buildDiscretization(spec, kFile);
  const long long n = whole.size();
  for (int parts : {2, 3, 7}) {
    long long next = 0;
    std::map<std::string, std::vector<int>> sets;
    for (int part = 0; part < parts; ++part) {
      const pf::PointCloud slab = pf::buildDiscretization(spec, kFile, part, parts);
      EXPECT_EQ(slab.numGlobal, n);
      ASSERT_EQ(slab.size(), n * (part + 1) / parts - n * part / parts);
      for (int i = 0; i < slab.size(); ++i, ++next) {
        ASSERT_EQ(slab.gid[i], next);
        for (int c = 0; c < 3; ++c) ASSERT_EQ(slab.x[3 * i + c], whole.x[3 * next + c]);
      }
      for (const auto& kv : slab.generatedNodeSets) sets[kv.first].insert(sets[kv.first].end(), kv.second.begin(), kv.second.end());
    }
    EXPECT_EQ(next, n);
    EXPECT_EQ(sets, whole.generatedNodeSets);
  }
}

// A Text File is read in byte ranges that start at line starts, cover the file once, and count their
// lines, so a bad line is named by its line in the whole file whichever range holds it.
TEST(Discretization, MeshFileRangesCoverTheFile) {
  std::string text = "# x y z block_id volume\n";
  for (int i = 0; i < 40; ++i) text += std::to_string(i) + " 0 0 1 0.5" + (i % 7 == 3 ? "   # note\n\n" : "\n");
  text += "40 0 0 1 0.5";  // no newline at the end
  pftest::writeTemp("pf_ranges.txt", text);
  ParameterList d;
  d.set("Type", std::string("Text File"));
  d.set("Input Mesh File", std::string("pf_ranges.txt"));
  const pf::DiscretizationSpec spec = pf::parseDiscretization(d, kFile, ::testing::TempDir());
  for (int parts : {1, 2, 5, 13}) {
    long long end = 0, lines = 0;
    std::vector<double> xs;
    for (int part = 0; part < parts; ++part) {
      const pf::MeshFileRange r = pf::meshFileRange(spec, kFile, part, parts);
      EXPECT_EQ(r.begin, end);
      EXPECT_TRUE(r.begin == 0 || r.begin == static_cast<long long>(text.size()) || text[r.begin - 1] == '\n');
      const pf::PointCloud c = pf::readMeshRange(spec, kFile, r, lines);
      for (int i = 0; i < c.size(); ++i) xs.push_back(c.x[3 * i]);
      end = r.end, lines += r.lines;
    }
    EXPECT_EQ(end, static_cast<long long>(text.size()));
    ASSERT_EQ(xs.size(), 41u);
    for (int i = 0; i < 41; ++i) EXPECT_EQ(xs[i], i);
  }
  // Line 30 of the file is bad; part 1 of 2 holds it and names it by its line in the whole file.
  std::string bad;
  for (int i = 1; i <= 40; ++i) bad += i == 30 ? "1 2 3\n" : "0 0 " + std::to_string(i) + " 1 0.5\n";
  pftest::writeTemp("pf_ranges_bad.txt", bad);
  d.set("Input Mesh File", std::string("pf_ranges_bad.txt"));
  const pf::DiscretizationSpec badSpec = pf::parseDiscretization(d, kFile, ::testing::TempDir());
  const pf::MeshFileRange first = pf::meshFileRange(badSpec, kFile, 0, 2), second = pf::meshFileRange(badSpec, kFile, 1, 2);
  EXPECT_EQ(pf::readMeshRange(badSpec, kFile, first, 0).size(), first.lines);
  EXPECT_INPUT_ERROR(pf::readMeshRange(badSpec, kFile, second, first.lines), kFile, "pf_ranges_bad.txt:30:");
}

// The paper reports 154 336 nodes for the plate with two fictitious layers. This is reproduced by a
// node grid (401 x 401 points including the edges), removing points strictly inside the hole
// (|c - centre| < r keeps the 12 lattice points lying exactly on the circle), and layers of 6 rows
// (1.5 mm = delta + dx) on two faces: 160801 - 11277 + 2 * 6 * 401 = 154336.
TEST(Discretization, PaperPlateCount) {
  const pf::PointCloud nodes = pftest::cloudOf(plate("Nodes", 1.5), kFile, ".");
  EXPECT_EQ(nodes.size(), 154336);
  EXPECT_EQ(nodes.generatedNodeSets.at("Bottom Layer").size(), 6u * 401u);
  EXPECT_EQ(nodes.generatedNodeSets.at("Top Layer").size(), 6u * 401u);
  EXPECT_TRUE(nodes.planar);
  EXPECT_DOUBLE_EQ(nodes.thickness, 1.0);
  EXPECT_DOUBLE_EQ(nodes.volume[0], 0.25 * 0.25 * 1.0);
  for (int i = 0; i < nodes.size(); ++i) {
    const double* p = &nodes.x[3 * i];
    ASSERT_GE(p[0] * p[0] + p[1] * p[1], 225.0);
    ASSERT_EQ(p[2], 0.0);
  }
  // Layer rows sit beyond the plate's outermost row, one spacing apart.
  const int top0 = nodes.generatedNodeSets.at("Top Layer").front();
  EXPECT_DOUBLE_EQ(nodes.x[3 * top0 + 1], 50.25);

  // Default cell-centred grid, layer width = the horizon 1.25 mm (5 rows): 148696 + 2 * 5 * 400.
  const pf::PointCloud cells = pftest::cloudOf(plate("Cell Centers", 0.0), kFile, ".", 1.25);
  EXPECT_EQ(cells.size(), 152696);
  EXPECT_EQ(cells.generatedNodeSets.at("Bottom Layer").size(), 5u * 400u);
}

TEST(Discretization, BoxWithCylindricalHoleAndLayers) {
  ParameterList d = boxWithBore();
  const pf::PointCloud c = pftest::cloudOf(d, kFile, ".");
  // 4x4x2 cells, centres at 0.5..3.5; the four central columns (distance 0.707) are removed, also
  // from the Front layer since the cylinder is unbounded along its axis.
  EXPECT_EQ(c.size(), (32 - 8) + 16 + (32 - 8));
  EXPECT_EQ(c.generatedNodeSets.at("Left Layer").size(), 2u * 4u * 2u);
  EXPECT_EQ(c.generatedNodeSets.at("Front Layer").size(), 4u * 4u * 2u - 4u * 2u);
  EXPECT_DOUBLE_EQ(c.volume[0], 1.0);
  EXPECT_FALSE(c.planar);
  // Layers need a width: none given and no default.
  d.remove("Layer Width");
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, "."), kFile, "Layer Width");
  d.set("X Length", 4.1);
  EXPECT_INPUT_ERROR(pftest::cloudOf(d, kFile, ".", 1.0), kFile, "'X Length'");
}

TEST(NodeSets, FromIdsFilesAndRegions) {
  const pf::PointCloud c = pftest::cloudOf(quickGrid(3, 2, 2), kFile, ".");
  const std::string dir = ::testing::TempDir();
  pftest::writeTemp("pf_ns.txt", "# ids\n3\n1 2\n2\n");
  ParameterList bc;
  bc.set("Listed", std::string("10 7 4 1 4"));
  bc.set("From File", std::string("pf_ns.txt"));
  bc.set("Single", 5);  // YAML writes a lone id as an int
  ParameterList& box = bc.sublist("Low Z");
  box.set("Type", std::string("Node Set Region"));
  box.set("Z Max", 0.0);
  ParameterList& face = bc.sublist("Top Y");
  face.set("Type", std::string("Node Set Region"));
  face.set("Face", std::string("Max Y"));
  const auto s = pftest::nodeSetsOf(bc, c, kFile, dir);
  EXPECT_EQ(s.at("Listed"), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(s.at("From File"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(s.at("Single"), (std::vector<int>{4}));
  EXPECT_EQ(s.at("Low Z"), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(s.at("Top Y"), (std::vector<int>{3, 4, 5, 9, 10, 11}));
  EXPECT_EQ(s.at("All").size(), 12u);
}

TEST(NodeSets, Errors) {
  const pf::PointCloud c = pftest::cloudOf(quickGrid(3, 2, 2), kFile, ".");
  const std::string dir = ::testing::TempDir();
  {
    // Ids the discretization does not have are dropped with a warning, as Peridigm does (its decks list
    // id 0); a set left with no node is kept empty rather than rejected.
    ParameterList bc;
    bc.set("Far Away", std::string("0 1 13"));
    bc.set("Only Zero", std::string("0"));
    const auto s = pftest::nodeSetsOf(bc, c, kFile, dir);
    EXPECT_EQ(s.at("Far Away"), (std::vector<int>{0}));
    EXPECT_TRUE(s.at("Only Zero").empty());
  }
  {
    ParameterList bc;
    ParameterList& r = bc.sublist("Nothing");
    r.set("Type", std::string("Node Set Region"));
    r.set("X Min", 100.0);
    EXPECT_INPUT_ERROR(pftest::nodeSetsOf(bc, c, kFile, dir), kFile, "node set 'Nothing' is empty");
  }
  {
    ParameterList bc;
    bc.set("Missing File", std::string("no_such_nodeset.txt"));
    EXPECT_INPUT_ERROR(pftest::nodeSetsOf(bc, c, kFile, dir), kFile, "no_such_nodeset.txt");
  }
  {
    pftest::writeTemp("pf_empty_ns.txt", "# nothing\n");
    ParameterList bc;
    bc.set("Empty File", std::string("pf_empty_ns.txt"));
    EXPECT_INPUT_ERROR(pftest::nodeSetsOf(bc, c, kFile, dir), kFile, "Empty File");
  }
}
