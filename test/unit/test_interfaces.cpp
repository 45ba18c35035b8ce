// Peridigm's Construct Interfaces rule (output/InterfaceMesh.hpp) on hand-made connectivity, the Interfaces deck's
// input rules, and Elastic's Stored_Elastic_Energy_Density (Peridigm's W) under a uniform expansion, where the
// deviatoric extension vanishes and W = kappa theta^2 / 2 with theta = 3 eps exactly.
#include <exodusII.h>

#include <gtest/gtest.h>

#include "LatticeFixture.hpp"
#include "core/StateStore.hpp"
#include "output/InterfaceMesh.hpp"
#include "test_input_helpers.hpp"

namespace {

pf::MeshConnectivity meshOf(const std::vector<std::vector<long long>>& elements) {
  pf::MeshConnectivity m;
  for (const auto& e : elements) {
    m.nodes.insert(m.nodes.end(), e.begin(), e.end());
    m.offsets.push_back(static_cast<long long>(m.nodes.size()));
  }
  return m;
}

}  // namespace

TEST(InterfaceRule, TwoHexahedraShareTheirFaceInTheFirstOnesFaceOrder) {
  // Hexahedron 0: nodes 1..8 (Exodus order); hexahedron 1 sits on its face {2, 6, 7, 3} (Exodus face 5: 1 5 6 2).
  const pf::MeshConnectivity m = meshOf({{1, 2, 3, 4, 5, 6, 7, 8}, {2, 9, 10, 3, 6, 11, 12, 7}});
  std::vector<long long> nodes;
  ASSERT_TRUE(pf::sharedFace(m, 0, 1, nodes));
  EXPECT_EQ(nodes, (std::vector<long long>{2, 6, 7, 3}));  // self's nodes 1 5 6 2
  ASSERT_TRUE(pf::sharedFace(m, 1, 0, nodes));
  EXPECT_EQ(nodes, (std::vector<long long>{2, 6, 7, 3}));  // from element 1's side: its face 2, nodes 0 4 7 3
}

TEST(InterfaceRule, TetrahedraShareATriangleAnEdgeIsNotAFace) {
  const pf::MeshConnectivity m = meshOf({{1, 2, 3, 4}, {2, 3, 4, 5}, {3, 4, 6, 7}});
  std::vector<long long> nodes;
  ASSERT_TRUE(pf::sharedFace(m, 0, 1, nodes));
  EXPECT_EQ(nodes, (std::vector<long long>{2, 3, 4}));  // in self's order
  EXPECT_FALSE(pf::sharedFace(m, 0, 2, nodes));         // nodes 3, 4 only
  EXPECT_TRUE(nodes.empty());
}

TEST(InterfaceRule, AHexahedronReadsEightIdsFromATetrahedronsStartAsPeridigmDoes) {
  // Hexahedron 0's face {1 2 3 4} (Exodus face 4: 0 1 2 3). Tetrahedron 1 holds nodes 1 and 2 of it, tetrahedron 2,
  // next in the file, nodes 3 and 4: reading 8 ids from tetrahedron 1's start finds all four, a quadrilateral
  // Peridigm builds although neither tetrahedron shares a face with the hexahedron.
  const pf::MeshConnectivity m = meshOf({{1, 2, 3, 4, 5, 6, 7, 8}, {1, 2, 9, 10}, {3, 4, 11, 12}});
  std::vector<long long> nodes;
  ASSERT_TRUE(pf::sharedFace(m, 0, 1, nodes));
  EXPECT_EQ(nodes, (std::vector<long long>{1, 2, 3, 4}));
  // The last element: nothing past the end is read; 2 ids of the face are not a face.
  EXPECT_FALSE(pf::sharedFace(m, 0, 2, nodes));
  // Three of the face's nodes in one tetrahedron: a triangle of the face's first three nodes (Peridigm's count).
  const pf::MeshConnectivity t = meshOf({{1, 2, 3, 4, 5, 6, 7, 8}, {1, 2, 3, 9}});
  ASSERT_TRUE(pf::sharedFace(t, 0, 1, nodes));
  EXPECT_EQ(nodes, (std::vector<long long>{1, 2, 3}));
}

namespace {

// A genesis file of one element of `type` on nodes 1..n at the corners of the unit square (n = 4) or cube (n = 8).
std::string writeOneElement(const std::string& name, const char* type, int n) {
  const std::string path = ::testing::TempDir() + name;
  int cpu = sizeof(double), io = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  ex_put_init(id, name.c_str(), 3, n, 1, 1, 0, 0);
  const double x[8] = {0, 1, 1, 0, 0, 1, 1, 0}, y[8] = {0, 0, 1, 1, 0, 0, 1, 1}, z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  ex_put_coord(id, x, y, z);
  ex_put_block(id, EX_ELEM_BLOCK, 1, type, 1, n, 0, 0, 0);
  const int conn[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  ex_put_conn(id, EX_ELEM_BLOCK, 1, conn, nullptr, nullptr);
  ex_close(id);
  return path;
}

}  // namespace

TEST(InterfaceInput, RestartAndNonHexTetMeshesAreRefusedNamingTheParameter) {
  const std::string hex = writeOneElement("interfaces_hex.g", "HEX8", 8);
  auto deck = pftest::deckFromXml(R"(<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Input Mesh File" type="string" value=")" + hex + R"("/>
    <Parameter name="Construct Interfaces" type="bool" value="true"/>
  </ParameterList>
  <ParameterList name="Materials"><ParameterList name="M">
    <Parameter name="Material Model" type="string" value="Elastic"/><Parameter name="Density" type="double" value="1"/>
    <Parameter name="Bulk Modulus" type="double" value="1"/><Parameter name="Shear Modulus" type="double" value="1"/>
  </ParameterList></ParameterList>
  <ParameterList name="Blocks"><ParameterList name="B">
    <Parameter name="Block Names" type="string" value="block_1"/>
    <Parameter name="Material" type="string" value="M"/><Parameter name="Horizon" type="double" value="5"/>
  </ParameterList></ParameterList>
  <ParameterList name="Solver"><Parameter name="Final Time" type="double" value="1"/>
    <ParameterList name="QuasiStatic"><Parameter name="Number of Load Steps" type="int" value="1"/></ParameterList>
  </ParameterList>
  <ParameterList name="Output"><Parameter name="Output Filename" type="string" value="out"/>
    <ParameterList name="Output Variables"><Parameter name="Displacement" type="bool" value="true"/></ParameterList>
  </ParameterList>
  <ParameterList name="Restart"><Parameter name="Checkpoint Frequency" type="int" value="1"/></ParameterList>
</ParameterList>)");
  EXPECT_INPUT_ERROR(pf::parseDeck(*deck, "deck.xml"), "deck.xml", "Construct Interfaces");
  deck->remove("Restart");
  EXPECT_TRUE(pf::parseDeck(*deck, "deck.xml").discretization.constructInterfaces);
  EXPECT_EQ(pf::readConnectivity(hex, "deck.xml").nodes.size(), 8u);
  // A mesh of QUAD4 elements: not Peridigm's hexahedra or tetrahedra.
  const std::string quad = writeOneElement("interfaces_quad.g", "QUAD4", 4);
  EXPECT_INPUT_ERROR(pf::readConnectivity(quad, "deck.xml"), "deck.xml", "Discretization/Construct Interfaces");
}

TEST(ElasticEnergyDensity, UniformExpansionGivesKappaThetaSquaredOverTwo) {
  // The centre of a 3D lattice (horizon 3 dx) under y = (1 + eps) x: e = eps |xi| on every bond, so theta =
  // 3 eps (m is the same sum) and the deviatoric extension is 0: W = kappa (3 eps)^2 / 2, V W the stored energy.
  const pftest::Lattice L = pftest::makeLattice(9, false, 1e-3, 3.0, 0.0, pf::Influence::One, true);
  auto mat = pftest::makeElastic(pf::Dimension::ThreeD, 200e9, 0.3, 0.0);
  pf::StateStore state;
  state.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
  mat->enableOutput("Stored_Elastic_Energy_Density");
  const double eps = 1e-3, kappa = 200e9 / (3.0 * (1.0 - 2.0 * 0.3));
  std::vector<double> y(L.x), force(L.x.size(), 0.0);
  for (double& c : y) c *= 1.0 + eps;
  mat->computeForce(L.view(), y.data(), state, force.data());
  const double W = state.trial("Stored_Elastic_Energy_Density")[0];
  // Round-off: theta and the extensions carry ~1e-16 relative of eps over some 100 bonds; W ~ 1.5e5 J/m^3.
  EXPECT_NEAR(W, 0.5 * kappa * 9.0 * eps * eps, 1e-9 * 0.5 * kappa * 9.0 * eps * eps);
  EXPECT_NEAR(state.trial("Stored_Elastic_Energy")[0], W * L.nodeVolume(), 1e-12 * W * L.nodeVolume());
}
