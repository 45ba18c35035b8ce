// Peridigm's "Time Dependent Critical Stretch" and "Initial Damage" damage models as the deck parser reads them,
// and an Exodus Mesh filter read whole (Discretization) or as Peridigm's Initial Damage reads it (triangles).
#include <cmath>

#include <exodusII.h>
#include <gtest/gtest.h>

#include "core/Expression.hpp"
#include "test_input_helpers.hpp"

namespace {

// Damage Models with one list "D" holding the given parameters (and sub-lists).
Teuchos::RCP<Teuchos::ParameterList> damageDeck(const std::string& inner) {
  return pftest::deckFromXml("<ParameterList><ParameterList name=\"Damage Models\"><ParameterList name=\"D\">" + inner +
                             "</ParameterList></ParameterList></ParameterList>");
}

std::string p(const std::string& name, const std::string& type, const std::string& value) {
  return "<Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>";
}

std::vector<pf::DamageModelSpec> parse(const std::string& inner, const std::string& dir = ".") {
  return pf::parseDamageModels(*damageDeck(inner), "deck.xml", dir);
}

// One quad (0,0,0) (1,0,0) (1,1,0) (0,1,0) in an Exodus file.
std::string writeQuad() {
  const std::string path = ::testing::TempDir() + "damage_variants_quad.g";
  int cpu = sizeof(double), io = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  EXPECT_GE(id, 0);
  ex_put_init(id, "quad", 3, 4, 1, 1, 0, 0);
  const double x[4] = {0, 1, 1, 0}, y[4] = {0, 0, 1, 1}, z[4] = {0, 0, 0, 0};
  ex_put_coord(id, x, y, z);
  ex_put_block(id, EX_ELEM_BLOCK, 1, "QUAD4", 1, 4, 0, 0, 0);
  const int conn[4] = {1, 2, 3, 4};
  ex_put_conn(id, EX_ELEM_BLOCK, 1, conn, nullptr, nullptr);
  ex_close(id);
  return path;
}

TEST(DamageVariants, TimeDependentCriticalStretchIsAnExpressionOfT) {
  const auto d = parse(p("Damage Model", "string", "Time Dependent Critical Stretch") +
                       p("Time Dependent Critical Stretch", "string",
                         "if(t &lt;= 7.0e-5){ value = 50.0; } else{ value = 0.015; }"));
  ASSERT_EQ(d.size(), 1u);
  ASSERT_TRUE(d[0].stretchOfTime);
  EXPECT_EQ((*d[0].stretchOfTime)(0, 0, 0, 0.0), 50.0);
  EXPECT_EQ((*d[0].stretchOfTime)(0, 0, 0, 8e-5), 0.015);
  EXPECT_EQ(d[0].criticalStretch, 0.0);  // the block's s_c comes from the expression
  EXPECT_INPUT_ERROR(parse(p("Damage Model", "string", "Time Dependent Critical Stretch") +
                           p("Time Dependent Critical Stretch", "string", "0.01*x")),
                     "deck.xml", "Damage Models/D/Time Dependent Critical Stretch");
  EXPECT_INPUT_ERROR(parse(p("Damage Model", "string", "Time Dependent Critical Stretch")), "deck.xml",
                     "Time Dependent Critical Stretch");
}

TEST(DamageVariants, InitialDamageNeedsBondFiltersAndBreaksNothingElse) {
  const std::string disk = "<ParameterList name=\"Bond Filters\"><ParameterList name=\"F\">" + p("Type", "string", "Disk") +
                           p("Center_X", "double", "0") + p("Center_Y", "double", "0") + p("Center_Z", "double", "0") +
                           p("Normal_X", "double", "0") + p("Normal_Y", "double", "0") + p("Normal_Z", "double", "1") +
                           p("Radius", "double", "1") + "</ParameterList></ParameterList>";
  const auto d = parse(p("Damage Model", "string", "Initial Damage") + disk);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].initialBreaks.disks.size(), 1u);
  EXPECT_TRUE(std::isinf(d[0].criticalStretch));  // no stretch ever exceeds it
  EXPECT_INPUT_ERROR(parse(p("Damage Model", "string", "Initial Damage")), "deck.xml", "Damage Models/D");
}

TEST(DamageVariants, ExodusMeshWholeInTheDiscretizationTrianglesInInitialDamage) {
  const std::string mesh = writeQuad();
  const std::string list = "<ParameterList name=\"Bond Filters\"><ParameterList name=\"F\">" +
                           p("Type", "string", "Exodus Mesh") + p("File Name", "string", mesh) +
                           "</ParameterList></ParameterList>";
  const pf::BondFilters whole =
      pf::parseBondFilters(pftest::deckFromXml("<ParameterList>" + list + "</ParameterList>")->sublist("Bond Filters"), "deck.xml", "Discretization/Bond Filters",
                           ".", false);
  const auto d = parse(p("Damage Model", "string", "Initial Damage") + list);
  ASSERT_EQ(whole.polygons.size(), 1u);
  ASSERT_EQ(d[0].initialBreaks.polygons.size(), 1u);
  EXPECT_EQ(whole.polygons[0].corners, 4);
  EXPECT_EQ(d[0].initialBreaks.polygons[0].corners, 3);
  // (0.1, 0.9) lies in the quad's half (0,0) (1,1) (0,1), outside the triangle of the first three nodes.
  const double a[3] = {0.1, 0.9, -1}, b[3] = {0.1, 0.9, 1}, c[3] = {0.9, 0.1, -1}, e[3] = {0.9, 0.1, 1};
  EXPECT_TRUE(pf::cuts(whole.polygons[0], a, b));
  EXPECT_FALSE(pf::cuts(d[0].initialBreaks.polygons[0], a, b));
  EXPECT_TRUE(pf::cuts(d[0].initialBreaks.polygons[0], c, e));
}

}  // namespace
