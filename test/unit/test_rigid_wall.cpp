// Rigid Wall: the kinematic enforcement against hand-computed cases (model/RigidWall.hpp) and its input
// rules (src/input/RigidWallInput.cpp). The whole-body behaviour (momentum taken = sum of the reaction
// times dt, np 1 = np 2) is checked on the Taylor bar (test/regression/taylor.cmake).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "model/RigidWall.hpp"
#include "test_input_helpers.hpp"

namespace {

// Two points, wall z = 0 with normal +z; point 0 behind it moving in, point 1 in front of it.
struct TwoPoints {
  std::vector<double> x = {0.0, 0.0, 0.1, 1.0, 0.0, 0.1};
  std::vector<double> mass = {2.0, 3.0};
  std::vector<double> u = {0.05, -0.02, -0.13, 0.0, 0.0, -0.05};
  std::vector<double> v = {4.0, 1.0, -30.0, 0.0, 0.0, -20.0};
  std::vector<pf::RigidWall> walls = {pf::RigidWall{"Anvil", {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0, 1}}};
};

}  // namespace

TEST(RigidWall, PointBehindThePlaneIsPutOnItAndStopsAlongTheNormal) {
  TwoPoints p;
  std::vector<double> reaction;
  const double dt = 1e-3;
  pf::enforceRigidWalls(p.walls, p.x, p.mass, dt, p.u.data(), p.v.data(), reaction);
  // Point 0: gap 0.1 - 0.13 = -0.03 -> u_z = -0.1 (on the plane), v_z = 0, tangential parts unchanged.
  // Exact in floating point: the gap and its removal are single operations on these values.
  EXPECT_DOUBLE_EQ(p.x[2] + p.u[2], 0.0);
  EXPECT_EQ(p.v[2], 0.0);
  EXPECT_EQ(p.u[0], 0.05);
  EXPECT_EQ(p.u[1], -0.02);
  EXPECT_EQ(p.v[0], 4.0);
  EXPECT_EQ(p.v[1], 1.0);
  // Point 1 (gap +0.05) untouched.
  EXPECT_EQ(p.u[5], -0.05);
  EXPECT_EQ(p.v[5], -20.0);
  // The wall took m |v_n| = 2 * 30 in one step: force on the body 6e4 N along +n.
  ASSERT_EQ(reaction.size(), 3u);
  EXPECT_EQ(reaction[0], 0.0);
  EXPECT_EQ(reaction[1], 0.0);
  EXPECT_DOUBLE_EQ(reaction[2], 2.0 * 30.0 / dt);
}

TEST(RigidWall, ObliqueWallRemovesOnlyTheNormalVelocity) {
  // Wall through (1, 0, 0) with normal (-1, -1, 0)/sqrt 2 (the body on the side x + y < 1); a point at
  // (1, 0.5, 0) (behind by 0.5/sqrt 2) moving with v = (2, 0, 0).
  const double s = 1.0 / std::sqrt(2.0);
  std::vector<pf::RigidWall> walls = {pf::RigidWall{"W", {1.0, 0.0, 0.0}, {-s, -s, 0.0}, {0}}};
  std::vector<double> x = {1.0, 0.5, 0.0}, mass = {1.0}, u = {0.0, 0.0, 0.0}, v = {2.0, 0.0, 0.0}, reaction;
  pf::enforceRigidWalls(walls, x, mass, 0.5, u.data(), v.data(), reaction);
  // Back on the plane x + y = 1 (round-off of a few operations on O(1) numbers).
  EXPECT_NEAR(x[0] + u[0] + x[1] + u[1], 1.0, 1e-15);
  // v_n = -sqrt 2 removed: v = (1, -1, 0), tangential (1, -1)/sqrt 2 * sqrt 2 kept; reaction m |v_n| / dt n.
  EXPECT_NEAR(v[0], 1.0, 1e-15);
  EXPECT_NEAR(v[1], -1.0, 1e-15);
  EXPECT_NEAR(reaction[0], -2.0, 1e-15);
  EXPECT_NEAR(reaction[1], -2.0, 1e-15);
}

TEST(RigidWall, SeparatingPointBehindThePlaneKeepsItsVelocity) {
  // A point found behind the plane but already moving away (possible only at the start): placed on the
  // plane, its velocity and the reaction untouched (the wall never pulls).
  std::vector<pf::RigidWall> walls = {pf::RigidWall{"W", {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0}}};
  std::vector<double> x = {0.0, 0.0, -0.5}, mass = {1.0}, u = {0.0, 0.0, 0.0}, v = {0.0, 0.0, 3.0}, reaction;
  pf::enforceRigidWalls(walls, x, mass, 0.1, u.data(), v.data(), reaction);
  EXPECT_EQ(u[2], 0.5);
  EXPECT_EQ(v[2], 3.0);
  EXPECT_EQ(reaction[2], 0.0);
}

// The wall's energy loss (RigidWall.hpp): a point arriving freely (a = 0) loses its normal kinetic energy
// m v_n^2 / 2 (the tangential part stays); a point resting on the wall, kicked into it by a constant
// acceleration a each Verlet step (v_n = dt a, gap = dt^2 a), loses nothing, since nothing moves. Both are
// exact identities of the formula's few operations on these values (1e-12 relative for round-off).
TEST(RigidWall, EnergyLossIsTheImpactsAndZeroForAPointResting) {
  std::vector<pf::RigidWall> walls = {pf::RigidWall{"W", {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0}}};
  std::vector<double> x = {0.0, 0.0, 0.0}, mass = {2.0}, reaction;
  const double dt = 1e-3;
  {
    std::vector<double> u = {0.0, 0.0, -30.0 * dt}, v = {5.0, 0.0, -30.0}, a = {0.0, 0.0, 0.0}, loss = {0.0};
    pf::enforceRigidWalls(walls, x, mass, dt, u.data(), v.data(), reaction, a.data(), loss.data());
    EXPECT_NEAR(loss[0], 0.5 * 2.0 * 30.0 * 30.0, 1e-12 * 900.0);
  }
  {
    const double acc = -4.0e3;  // pushed into the wall by the body behind it
    std::vector<double> u = {0.0, 0.0, dt * dt * acc}, v = {0.0, 0.0, dt * acc}, a = {0.0, 0.0, acc}, loss = {0.0};
    pf::enforceRigidWalls(walls, x, mass, dt, u.data(), v.data(), reaction, a.data(), loss.data());
    EXPECT_NEAR(loss[0], 0.0, 1e-12 * 0.5 * 2.0 * (dt * acc) * (dt * acc));
    EXPECT_EQ(v[2], 0.0);
  }
}

namespace {

std::string deckWith(const std::string& wall, const std::string& solver) {
  return R"(<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Cylinder"/>
    <Parameter name="Radius" type="double" value="2"/>
    <Parameter name="Length" type="double" value="6"/>
    <Parameter name="Spacing" type="double" value="1"/>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Al">
      <Parameter name="Material Model" type="string" value="Elastic"/>
      <Parameter name="Density" type="double" value="2700"/>
      <Parameter name="Bulk Modulus" type="double" value="68e9"/>
      <Parameter name="Shear Modulus" type="double" value="26e9"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="B">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Al"/>
      <Parameter name="Horizon" type="double" value="3.05"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <ParameterList name="Anvil">
      <Parameter name="Type" type="string" value="Rigid Wall"/>
)" + wall + R"(
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="1e-6"/>
)" + solver + R"(
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="out"/>
  </ParameterList>
</ParameterList>)";
}

const std::string kVerlet = R"(<ParameterList name="Verlet"/>)";
const std::string kNormal = R"(<Parameter name="Normal Z" type="double" value="2.0"/>)";

}  // namespace

TEST(RigidWallInput, ParsedWithAUnitNormal) {
  const pf::Deck d = pf::parseDeck(*pftest::deckFromXml(deckWith(kNormal, kVerlet)), "deck.xml");
  ASSERT_EQ(d.walls.size(), 1u);
  EXPECT_EQ(d.walls[0].name, "Anvil");
  EXPECT_EQ(d.walls[0].nodeSet, "All");
  EXPECT_EQ(d.walls[0].normal[2], 1.0);  // 2 / 2, exactly
  EXPECT_TRUE(d.conditions.empty());      // not a nodal condition
}

TEST(RigidWallInput, ZeroNormalIsRefused) {
  EXPECT_INPUT_ERROR(pf::parseDeck(*pftest::deckFromXml(deckWith("", kVerlet)), "deck.xml"), "deck.xml",
                     "Boundary Conditions/Anvil: 'Normal X'");
}

TEST(RigidWallInput, UnknownParameterIsRefused) {
  EXPECT_INPUT_ERROR(pf::parseDeck(*pftest::deckFromXml(deckWith(
                                       kNormal + R"(<Parameter name="Value" type="double" value="1"/>)", kVerlet)),
                                   "deck.xml"),
                     "deck.xml", "Value");
}

TEST(RigidWallInput, UnknownNodeSetIsRefused) {
  EXPECT_INPUT_ERROR(pf::parseDeck(*pftest::deckFromXml(deckWith(
                                       kNormal + R"(<Parameter name="Node Set" type="string" value="Face"/>)", kVerlet)),
                                   "deck.xml"),
                     "deck.xml", "'Node Set' = 'Face'");
}

TEST(RigidWallInput, OnlyVerletEnforcesIt) {
  const std::string qs = R"(<ParameterList name="QuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/></ParameterList>)";
  EXPECT_INPUT_ERROR(pf::parseDeck(*pftest::deckFromXml(deckWith(kNormal, qs)), "deck.xml"), "deck.xml",
                     "Boundary Conditions/Anvil: a Rigid Wall is enforced by the Verlet solver only; 'Solver' is 'QuasiStatic'");
}
