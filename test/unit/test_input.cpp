// Schema validation, readInput, expressions and boundary conditions.
#include <cmath>
#include <filesystem>
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "discretization/Discretization.hpp"
#include "core/Expression.hpp"
#include "input/Input.hpp"
#include "input/InputSchema.hpp"
#include "input/ListReader.hpp"
#include "discretization/NodeSets.hpp"
#include "test_input_helpers.hpp"

using pftest::deckFromXml;

namespace {

const char* kFile = "deck.xml";

std::string baseDeck() {
  return R"(<ParameterList>
  <Parameter name="Verbose" type="bool" value="false"/>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="PdQuickGrid"/>
    <ParameterList name="TensorProduct3DMeshGenerator">
      <Parameter name="X Origin" type="double" value="0"/>
      <Parameter name="Y Origin" type="double" value="0"/>
      <Parameter name="Z Origin" type="double" value="0"/>
      <Parameter name="X Length" type="double" value="3"/>
      <Parameter name="Y Length" type="double" value="2"/>
      <Parameter name="Z Length" type="double" value="2"/>
      <Parameter name="Number Points X" type="int" value="3"/>
      <Parameter name="Number Points Y" type="int" value="2"/>
      <Parameter name="Number Points Z" type="int" value="2"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Steel">
      <Parameter name="Material Model" type="string" value="Elastic"/>
      <Parameter name="Density" type="double" value="7800"/>
      <Parameter name="Bulk Modulus" type="double" value="130e9"/>
      <Parameter name="Shear Modulus" type="double" value="78e9"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="My Block">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Steel"/>
      <Parameter name="Horizon" type="double" value="1.75"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <Parameter name="Min X Node Set" type="string" value="1 4 7 10"/>
    <ParameterList name="Right Face">
      <Parameter name="Type" type="string" value="Node Set Region"/>
      <Parameter name="Face" type="string" value="Max X"/>
    </ParameterList>
    <ParameterList name="Fix Left">
      <Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="Min X Node Set"/>
      <Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="0.0"/>
    </ParameterList>
    <ParameterList name="Pull Right">
      <Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="Right Face"/>
      <Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="0.01*t"/>
    </ParameterList>
    <ParameterList name="Gravity">
      <Parameter name="Type" type="string" value="Body Force"/>
      <Parameter name="Node Set" type="string" value="All"/>
      <Parameter name="Coordinate" type="string" value="z"/>
      <Parameter name="Value" type="double" value="-9.81"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="1.0"/>
    <ParameterList name="QuasiStatic">
      <Parameter name="Number of Load Steps" type="int" value="2"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="out"/>
    <Parameter name="Reactions" type="string" value="Min X Node Set, Right Face"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
    </ParameterList>
    <ParameterList name="Probes">
      <ParameterList name="Centre">
        <Parameter name="X" type="double" value="1.5"/>
        <Parameter name="Y" type="double" value="1.0"/>
        <Parameter name="Variables" type="string" value="Displacement, Equivalent_Plastic_Strain"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>)";
}

Teuchos::RCP<Teuchos::ParameterList> base() { return deckFromXml(baseDeck()); }

}  // namespace

TEST(InputSchema, BaseDeckIsValid) { EXPECT_NO_THROW(pf::parseDeck(*base(), kFile)); }

TEST(InputSchema, UnknownParameterNamesItsPath) {
  auto p = base();
  p->sublist("Blocks").sublist("My Block").set("Horizn", 1.0);
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "Blocks/My Block: unknown parameter 'Horizn'");
}

TEST(InputSchema, UnknownSubListNamesItsPath) {
  auto p = base();
  p->sublist("Solver").sublist("QuasiStatic").sublist("Extra");
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "Solver/QuasiStatic: unknown sub-list 'Extra'");
  auto q = base();
  q->sublist("Contacts");
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "unknown sub-list 'Contacts'");
}

// Damage Models: parsed once into DamageModelSpecs, named by the blocks; bad input names file and parameter.
TEST(InputSchema, DamageModels) {
  auto p = base();
  Teuchos::ParameterList& d = p->sublist("Damage Models").sublist("Brittle");
  d.set("Damage Model", std::string("Critical Stretch"));
  d.set("Critical Stretch", 0.02);
  p->sublist("Blocks").sublist("My Block").set("Damage Model", std::string("Brittle"));
  const pf::Deck deck = pf::parseDeck(*p, kFile);
  ASSERT_EQ(deck.damageModels.size(), 1u);
  EXPECT_EQ(deck.damageModels[0].criticalStretch, 0.02);
  EXPECT_EQ(deck.blocks[0].damageModel, "Brittle");
  EXPECT_EQ(deck.damageModel("Brittle"), &deck.damageModels[0]);

  auto q = deckFromXml(baseDeck());
  q->sublist("Damage Models").sublist("Brittle").set("Damage Model", std::string("Critical Energy"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "Damage Models/Brittle: unknown 'Damage Model' = 'Critical Energy'");
  auto r = deckFromXml(baseDeck());
  r->sublist("Damage Models").sublist("Brittle").set("Damage Model", std::string("Critical Stretch"));
  r->sublist("Damage Models").sublist("Brittle").set("Critical Stretch", -0.1);
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "Damage Models/Brittle: 'Critical Stretch'");
  auto u = deckFromXml(baseDeck());
  u->sublist("Blocks").sublist("My Block").set("Damage Model", std::string("Missing"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*u, kFile), kFile,
                     "Blocks/My Block: 'Damage Model' = 'Missing' is not defined in Damage Models (defined: none)");
}

TEST(InputSchema, MissingMaterial) {
  auto p = base();
  p->sublist("Blocks").sublist("My Block").set("Material", std::string("Aluminium"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "'Material' = 'Aluminium'");
}

TEST(InputSchema, NonPositiveHorizon) {
  auto p = base();
  p->sublist("Blocks").sublist("My Block").set("Horizon", -1.0);
  const std::string msg = pftest::inputErrorOf([&] { pf::parseDeck(*p, "plate.xml"); });
  EXPECT_EQ(msg, "plate.xml: Blocks/My Block: 'Horizon' must be positive (got -1)");
}

TEST(InputSchema, WrongTypeAndMissingRequired) {
  auto p = base();
  p->sublist("Blocks").sublist("My Block").set("Horizon", std::string("big"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "Blocks/My Block/Horizon");  // an expression in x, y, z
  auto q = base();
  q->sublist("Solver").remove("Final Time");
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "missing required parameter 'Final Time'");
  auto r = base();
  r->remove("Blocks");
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "missing required sub-list 'Blocks'");
}

TEST(InputSchema, UnknownMaterialModelAndParameter) {
  auto p = base();
  p->sublist("Materials").sublist("Steel").set("Material Model", std::string("Rubber"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "unknown 'Material Model' = 'Rubber'");
  auto q = base();
  q->sublist("Materials").sublist("Steel").set("Yield Strss", 1.0);
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "Materials/Steel: unknown parameter 'Yield Strss'");
  auto r = base();
  r->sublist("Materials").sublist("Steel").remove("Density");
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "missing required parameter 'Density'");
}

TEST(InputSchema, MaterialInputConvertsValues) {
  auto p = base();
  p->sublist("Materials").sublist("Steel").set("Plane Stress", true);
  p->sublist("Materials").sublist("Steel").set("Density", 7800);  // int where a double is expected
  const pf::MaterialInput in = pf::materialInputFor(p->sublist("Materials").sublist("Steel"), "Steel", kFile);
  EXPECT_EQ(in.name, "Steel");
  EXPECT_DOUBLE_EQ(in.get("Density"), 7800.0);
  EXPECT_DOUBLE_EQ(in.get("Plane Stress"), 1.0);
  EXPECT_EQ(in.strings.at("Material Model"), "Elastic");
}

TEST(InputSchema, UnknownInfluenceFunction) {
  auto p = base();
  p->sublist("Discretization").set("Influence Function", std::string("Cubic"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "'Influence Function' = 'Cubic'");
}

TEST(InputSchema, SolverChoiceIsExactlyOne) {
  auto p = base();
  p->sublist("Solver").sublist("Verlet").set("Fixed dt", 1e-8);
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "exactly one solver sub-list");
  auto q = base();
  q->sublist("Solver").remove("QuasiStatic");
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "exactly one solver sub-list");
  // NOXQuasiStatic: its scalar options are checked, NOX's own sub-lists pass through, others are errors.
  auto r = base();
  r->sublist("Solver").remove("QuasiStatic");
  r->sublist("Solver").sublist("NOXQuasiStatic").set("Number of Load Steps", 2);
  r->sublist("Solver").sublist("NOXQuasiStatic").sublist("Direction").set("Method", std::string("Newton"));
  EXPECT_NO_THROW(pf::parseDeck(*r, kFile));
  r->sublist("Solver").sublist("NOXQuasiStatic").sublist("Anything").set("Goes", 1);
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "unknown sub-list 'Anything'");
}

TEST(InputSchema, BoundaryConditionErrors) {
  auto p = base();
  p->sublist("Boundary Conditions").sublist("Fix Left").set("Node Set", std::string("Nowhere"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "'Node Set' = 'Nowhere'");
  auto q = base();
  q->sublist("Boundary Conditions").sublist("Fix Left").set("Coordinate", std::string("w"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "'Coordinate'");
  auto r = base();
  r->sublist("Boundary Conditions").sublist("Fix Left").set("Value", std::string("2*q"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "Boundary Conditions/Fix Left/Value");
  auto s = base();
  s->sublist("Boundary Conditions").sublist("Fix Left").set("Type", std::string("Prescribed Temperature"));
  // A temperature condition is a scalar: the sub-list's Coordinate is refused.
  EXPECT_INPUT_ERROR(pf::parseDeck(*s, kFile), kFile, "'Coordinate' does not apply to a Prescribed Temperature");
  auto s2 = base();
  s2->sublist("Boundary Conditions").sublist("Fix Left").set("Type", std::string("Prescribed Pressure"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*s2, kFile), kFile, "'Type' = 'Prescribed Pressure'");
}

TEST(InputSchema, OutputErrors) {
  auto p = base();
  p->sublist("Output").sublist("Output Variables").set("Stress", true);
  EXPECT_INPUT_ERROR(pf::parseDeck(*p, kFile), kFile, "Output/Output Variables: unknown parameter 'Stress'");
  auto q = base();
  q->sublist("Output").sublist("Probes").sublist("Centre").set("Variables", std::string("Heat_Flux"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "'Heat_Flux'");
  auto r = base();
  r->sublist("Output").set("Reactions", std::string("Min X Node Set, Nowhere"));
  EXPECT_INPUT_ERROR(pf::parseDeck(*r, kFile), kFile, "'Reactions' names undefined node set 'Nowhere'");
}

// Peridigm takes every top-level list whose name contains "Output" as an output list (Peridigm.cpp,
// initializeOutputManager): "Output Data" (its VariableHorizonParsing and contact decks) is one.
TEST(InputSchema, OutputListsAreThoseWhoseNameContainsOutput) {
  auto p = base();
  Teuchos::ParameterList data = p->sublist("Output");
  data.set("Output Filename", std::string("data"));
  p->set("Output Data", data);
  p->set("Output2", data);
  p->sublist("Output2").set("Output Filename", std::string("second"));
  const pf::Deck deck = pf::parseDeck(*p, kFile);
  ASSERT_EQ(deck.outputs.size(), 3u);  // Output, the numbered Output2, then the others in the deck's order
  EXPECT_EQ(deck.outputs[0].filename, "out");
  EXPECT_EQ(deck.outputs[1].filename, "second");
  EXPECT_EQ(deck.outputs[2].filename, "data");
  auto q = base();
  q->set("Output01", data);
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "'Output01': a numbered Output list");
}

// Peridigm leaves a prescribed displacement out of the initial state (its increments start at the first step).
TEST(InputSchema, ApplyAtInitialTimeIsAPrescribedDisplacementsSwitch) {
  const pf::Deck deck = pf::parseDeck(*base(), kFile);
  ASSERT_FALSE(deck.conditions.empty());
  EXPECT_EQ(deck.conditions[0].kind, pf::ConditionSpec::Kind::PrescribedDisplacement);
  EXPECT_FALSE(deck.conditions[0].atInitialTime);
  auto p = base();
  p->sublist("Boundary Conditions").sublist("Fix Left").set("Apply At Initial Time", true);
  EXPECT_TRUE(pf::parseDeck(*p, kFile).conditions[0].atInitialTime);
  auto q = base();
  Teuchos::ParameterList& push = q->sublist("Boundary Conditions").sublist("Push");
  push.set("Type", std::string("Body Force"));
  push.set("Node Set", std::string("Min X Node Set"));
  push.set("Coordinate", std::string("x"));
  push.set("Value", std::string("1.0"));
  push.set("Apply At Initial Time", true);
  EXPECT_INPUT_ERROR(pf::parseDeck(*q, kFile), kFile, "'Apply At Initial Time' applies to a Prescribed Displacement only");
}

TEST(Input, ReadsXmlAndYamlAndNamesBadFiles) {
  const std::string xml = pftest::writeTemp("pf_deck.xml", baseDeck());
  auto p = pf::readInput(xml);
  EXPECT_NO_THROW(pf::parseDeck(*p, xml));
  EXPECT_EQ(pf::inputDirectory("/a/b/deck.xml"), "/a/b");
  EXPECT_EQ(pf::inputDirectory("deck.xml"), ".");

  const std::string yaml = pftest::writeTemp("pf_deck.yaml", R"(%YAML 1.1
---
ANONYMOUS:
  Solver:
    Final Time: 2.5
    Verlet:
      Safety Factor: 0.8
  Boundary Conditions:
    Ends: "1 2"
    Pull:
      Type: Prescribed Displacement
      Node Set: Ends
      Coordinate: x
      Value: 0.0
...
)");
  auto y = pf::readInput(yaml);
  EXPECT_DOUBLE_EQ(pf::getNumber(y->sublist("Solver"), "Final Time"), 2.5);
  EXPECT_EQ(pf::getText(y->sublist("Boundary Conditions"), "Ends", ""), "1 2");
  EXPECT_EQ(pf::scalarAsText(y->sublist("Boundary Conditions").sublist("Pull").getEntry("Value")), "0");

  EXPECT_INPUT_ERROR(pf::readInput("/nonexistent/deck.xml"), "/nonexistent/deck.xml", "cannot open");
  const std::string bad = pftest::writeTemp("pf_bad.xml", "<ParameterList><Parameter name=\"a\"</ParameterList>");
  EXPECT_INPUT_ERROR(pf::readInput(bad), bad, "cannot parse XML");
}

TEST(Expression, PeridigmStyleAndBodies) {
  pf::Expression ramp("-0.1*t/0.00005", "ctx");
  EXPECT_NEAR(ramp(0, 0, 0, 0.00005), -0.1, 1e-15);
  EXPECT_FALSE(ramp.dependsOnSpace());
  pf::Expression body("value = -0.1*t/0.00005;", "ctx");
  EXPECT_NEAR(body(0, 0, 0, 0.000025), -0.05, 1e-15);
  pf::Expression space("0.001*x + 2*y - z*1e-3", "ctx");
  EXPECT_TRUE(space.dependsOnSpace());
  EXPECT_NEAR(space(1, 2, 3, 0), 0.001 + 4 - 0.003, 1e-14);
  pf::Expression exponent("1e-3*t", "ctx");  // the 'e' of 1e-3 is not a variable
  EXPECT_FALSE(exponent.dependsOnSpace());
  pf::Expression zero("0.0", "ctx");
  EXPECT_EQ(zero(5, 5, 5, 5), 0.0);
  EXPECT_INPUT_ERROR(pf::Expression("1 +", "in.xml: Boundary Conditions/B/Value"), "in.xml",
                     "Boundary Conditions/B/Value");
  EXPECT_INPUT_ERROR(pf::Expression("  ", "in.xml: Boundary Conditions/B/Value"), "in.xml", "empty");
}

// The cyclic history of the paper: 0 -> +0.25 (t 20) -> -0.25 (t 60) -> +0.25 (t 100) -> 0 (t 120),
// written exactly as docs/input.md shows it.
TEST(Expression, CyclicPiecewiseLinearHistory) {
  const std::string text =
      "if (t <= 20) { value = 0.25*t/20; }\n"
      "else if (t <= 60) { value = 0.25 - 0.5*(t - 20)/40; }\n"
      "else if (t <= 100) { value = -0.25 + 0.5*(t - 60)/40; }\n"
      "else { value = 0.25 - 0.25*(t - 100)/20; }";
  pf::Expression h(text, "ctx");
  EXPECT_FALSE(h.dependsOnSpace());
  const double knots[][2] = {{0, 0},  {10, 0.125}, {20, 0.25}, {40, 0},      {60, -0.25},
                             {80, 0}, {100, 0.25}, {110, 0.125}, {120, 0.0}};
  for (const auto& k : knots) EXPECT_NEAR(h(0, 0, 0, k[0]), k[1], 1e-14) << "t = " << k[0];

  // The XML form of docs/input.md (newlines in the attribute, &lt; for <).
  auto p = deckFromXml(R"(<ParameterList><Parameter name="Value" type="string" value="
  if (t &lt;= 20) { value = 0.25*t/20; }
  else if (t &lt;= 60) { value = 0.25 - 0.5*(t - 20)/40; }
  else if (t &lt;= 100) { value = -0.25 + 0.5*(t - 60)/40; }
  else { value = 0.25 - 0.25*(t - 100)/20; }"/></ParameterList>)");
  pf::Expression fromXml(p->get<std::string>("Value"), "ctx");
  for (const auto& k : knots) EXPECT_NEAR(fromXml(0, 0, 0, k[0]), k[1], 1e-14) << "t = " << k[0];
}

TEST(BoundaryConditions, ParsedWithNodeSets) {
  auto p = base();
  const pf::PointCloud c = pftest::cloudOf(p->sublist("Discretization"), kFile, ".");
  const auto sets = pftest::nodeSetsOf(p->sublist("Boundary Conditions"), c, kFile, ".");
  EXPECT_EQ(sets.at("Min X Node Set"), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(sets.at("Right Face"), (std::vector<int>{2, 5, 8, 11}));
  EXPECT_EQ(sets.at("All").size(), 12u);
  const auto bcs = pf::parseDeck(*p, kFile).conditions;
  ASSERT_EQ(bcs.size(), 3u);
  EXPECT_EQ(bcs[0].name, "Fix Left");
  EXPECT_EQ(bcs[0].kind, pf::ConditionSpec::Kind::PrescribedDisplacement);
  EXPECT_EQ(bcs[0].coordinate, 0);
  EXPECT_EQ(bcs[1].nodeSet, "Right Face");
  EXPECT_NEAR((*bcs[1].value)(0, 0, 0, 2.0), 0.02, 1e-15);
  EXPECT_EQ(bcs[2].kind, pf::ConditionSpec::Kind::BodyForce);
  EXPECT_EQ(bcs[2].coordinate, 2);
  EXPECT_NEAR((*bcs[2].value)(0, 0, 0, 0), -9.81, 1e-15);
}

namespace {
// Peridigm's decks in the shared reference data beside the repository (../shared; absent in a user's clone,
// where the test skips), located from this source file as RegressionDecks locates test/regression.
const std::string kPeridigm =
    (std::filesystem::path(__FILE__).parent_path() / "../../../shared/reference/peridigm/").lexically_normal().string();
bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}
}  // namespace

TEST(PeridigmDecks, ValidateAndBuildUnmodified) {
  for (const char* name : {"Compression_QS_3x2x2", "Compression_QS_3x2x2_TextFile"}) {
    const std::string deck = kPeridigm + name + "/" + name + ".xml";
    if (!exists(deck)) GTEST_SKIP() << deck << " not present";
    auto p = pf::readInput(deck);
    ASSERT_NO_THROW(pf::parseDeck(*p, deck)) << deck;
    const std::string dir = pf::inputDirectory(deck);
    const pf::Deck d = pf::parseDeck(*p, deck, dir);
    const pf::PointCloud c = pf::buildDiscretization(d.discretization, deck);
    EXPECT_EQ(c.size(), 12);
    const auto sets = pf::resolveNodeSets(d.nodeSets, c, deck);
    EXPECT_EQ(sets.size(), d.nodeSets.size() + 1);  // the deck's and "All"
    for (const pf::NodeSetSpec& n : d.nodeSets) EXPECT_FALSE(sets.at(n.name).empty()) << n.name;
    const auto& bcs = d.conditions;
    EXPECT_EQ(bcs.size(), 4u);
    EXPECT_NEAR((*bcs[1].value)(0, 0, 0, 0.00005), -0.1, 1e-15);
  }
}

// Every deck under test/regression must pass the validator (located from this source file, since
// the build passes no source-directory define).
TEST(RegressionDecks, Validate) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(__FILE__).parent_path().parent_path() / "regression";
  if (!fs::exists(root)) GTEST_SKIP() << root << " not present";
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".xml") continue;
    const std::string deck = entry.path().string();
    auto p = pf::readInput(deck);
    EXPECT_NO_THROW(pf::parseDeck(*p, deck)) << pftest::inputErrorOf([&] { pf::parseDeck(*p, deck); });
    ++count;
  }
  if (count == 0) GTEST_SKIP() << "no regression decks";
}

// Two output lists of one file: Peridigm's gold file is the first list's alone (its suite decks' second lists add
// globals, at the same or another frequency), so a later list of the same file is dropped.
TEST(InputSchema, OutputListsSharingAFile) {
  auto list = [](Teuchos::ParameterList& o, const std::vector<std::string>& vars) {
    o.set("Output Filename", std::string("shared"));
    for (const std::string& v : vars) o.sublist("Output Variables").set(v, true);
  };
  auto p = base();
  list(p->sublist("Output1"), {"Displacement"});
  list(p->sublist("Output2"), {"Force"});
  p->sublist("Output2").set("Output Frequency", 2);
  const pf::Deck d = pf::parseDeck(*p, kFile);
  ASSERT_EQ(d.outputs.size(), 2u);  // Output and Output1; Output2 dropped
  EXPECT_EQ(d.outputs[1].listName, "Output1");
  EXPECT_EQ(d.outputs[1].variables, std::vector<std::string>{"Displacement"});
  EXPECT_EQ(d.outputs[1].frequency, 1);
}
