// The typed input layer: declared ranges, defaults and choices, strict numbers, pass-through lists and the
// solver registry, each against the rule it states (no reference to the code's own output).
#include <gtest/gtest.h>

#include <cmath>

#include "core/Parameters.hpp"
#include "core/SolverEntry.hpp"
#include "input/Input.hpp"
#include "input/ListReader.hpp"
#include "solvers/Solver.hpp"
#include "test_input_helpers.hpp"

namespace {

using S = pf::ParameterSpec;
const char* kFile = "specs.xml";

TEST(ParameterSpec, RangesAcceptTheirBoundsAndRefuseWhatIsOutside) {
  const S positive = S::real("a").positive(), atLeastOne = S::integer("n").atLeast(1), half = S::real("f").nonNegative().below(0.5);
  EXPECT_EQ(positive.rangeError(1e-300), "");
  EXPECT_EQ(positive.rangeError(0.0), "must be positive (got 0)");
  EXPECT_NE(positive.rangeError(-1.0), "");
  EXPECT_EQ(atLeastOne.rangeError(1.0), "");
  EXPECT_EQ(atLeastOne.rangeError(0.0), "must be at least 1 (got 0)");
  EXPECT_EQ(half.rangeError(0.0), "");
  EXPECT_EQ(half.rangeError(0.5), "must be in [0, 0.5) (got 0.5)");
  EXPECT_EQ(half.rangeText(), "in [0, 0.5)");
  const S unit = S::real("d").positive().atMost(1.0);  // atMost: the upper bound is admissible
  EXPECT_EQ(unit.rangeError(1.0), "");
  EXPECT_EQ(unit.rangeError(1.5), "must be in (0, 1] (got 1.5)");
  EXPECT_EQ(S::real("x").atMost(2.0).rangeText(), "<= 2");
  EXPECT_EQ(S::real("x").rangeText(), "");
  EXPECT_FALSE(S::real("x").hasRange());
}

TEST(ReadList, DefaultsAreOfferedButNotGiven) {
  Teuchos::ParameterList l;
  l.set("Given", 2.0);
  const pf::ParameterValues v = pf::readList(
      l, {S::real("Given").need(), S::real("Factor").byDefault("0.8"), S::flag("Loud").byDefault("false"),
          S::text("Mode").byDefault("Fast").oneOf({"Fast", "Slow"}), S::real("Optional")},
      {}, kFile, "List");
  EXPECT_TRUE(v.has("Given"));
  EXPECT_FALSE(v.has("Factor"));
  EXPECT_EQ(v.get("Factor"), 0.8);  // the same double as the literal 0.8
  EXPECT_FALSE(v.flag("Loud"));
  EXPECT_EQ(v.text("Mode"), "Fast");
  EXPECT_EQ(v.get("Optional", -1.0), -1.0);
  EXPECT_INPUT_ERROR(v.get("Optional"), kFile, "'Optional'");
}

TEST(ReadList, RefusesWrongTypesRangesAndChoicesNamingThePath) {
  const std::vector<S> specs = {S::integer("Steps").atLeast(1), S::text("Mode").oneOf({"Fast", "Slow"}),
                                S::real("Width").positive()};
  Teuchos::ParameterList a;
  a.set("Steps", 2.5);
  EXPECT_INPUT_ERROR(pf::readList(a, specs, {}, kFile, "Solver/X"), kFile, "Solver/X: 'Steps' must be a int");
  Teuchos::ParameterList b;
  b.set("Steps", 0);
  EXPECT_INPUT_ERROR(pf::readList(b, specs, {}, kFile, "Solver/X"), kFile, "'Steps' must be at least 1 (got 0)");
  Teuchos::ParameterList c;
  c.set("Mode", std::string("Medium"));
  EXPECT_INPUT_ERROR(pf::readList(c, specs, {}, kFile, "Solver/X"), kFile, "'Mode' = 'Medium' is not one of 'Fast', 'Slow'");
  Teuchos::ParameterList d;
  d.set("Width", -0.0);
  EXPECT_INPUT_ERROR(pf::readList(d, specs, {}, kFile, "Solver/X"), kFile, "'Width' must be positive");
  Teuchos::ParameterList e;
  e.set("Widht", 1.0);
  EXPECT_INPUT_ERROR(pf::readList(e, specs, {}, kFile, "Solver/X"), kFile, "unknown parameter 'Widht'");
}

std::string deckWith(const std::string& parameter) {
  return "<ParameterList>\n  <ParameterList name=\"Blocks\">\n    " + parameter + "\n  </ParameterList>\n</ParameterList>\n";
}

TEST(StrictXml, NumbersAreReadWholeAndOnce) {
  struct Case {
    const char* parameter;
    const char* words;
  } bad[] = {
      {R"(<Parameter name="Horizon" type="double" value="0.003abc"/>)", "'Horizon' = '0.003abc' is not a number"},
      {R"(<Parameter name="Horizon" type="double" value="1 2 3"/>)", "is not a number"},
      {R"(<Parameter name="Horizon" type="double" value=""/>)", "is not a number"},
      {R"(<Parameter name="Horizon" type="double" value="inf"/>)", "not a finite number"},
      {R"(<Parameter name="Horizon" type="double" value="nan"/>)", "not a finite number"},
      {R"(<Parameter name="Horizon" type="double" value="1e400"/>)", "not a finite number"},
      {R"(<Parameter name="Steps" type="int" value="2.5"/>)", "'Steps' = '2.5' is not an integer"},
      {R"(<Parameter name="Steps" type="int" value="3000000000"/>)", "out of the int range"},
      {R"(<ParameterList name="L"/><ParameterList name="L"/>)", "sub-list 'L' is given twice"},
  };
  for (const Case& c : bad) {
    const std::string path = pftest::writeTemp("strict.xml", deckWith(c.parameter));
    EXPECT_INPUT_ERROR(pf::readInput(path), path, c.words);
    EXPECT_INPUT_ERROR(pf::readInput(path), path, "Blocks");
  }
  const std::string good = pftest::writeTemp(
      "strict_ok.xml", deckWith(R"(<Parameter name="Horizon" type="double" value=" 3.015e-3 "/><Parameter name="Steps" type="int" value="-7"/>)"));
  const auto p = pf::readInput(good);
  EXPECT_EQ(p->sublist("Blocks").get<double>("Horizon"), 3.015e-3);
  // A parameter given twice is read as Teuchos reads it: the last value wins (Peridigm's decks rely on it).
  const std::string twice = pftest::writeTemp(
      "strict_twice.xml", deckWith(R"(<Parameter name="H" type="double" value="1"/><Parameter name="H" type="double" value="2"/>)"));
  EXPECT_EQ(pf::readInput(twice)->sublist("Blocks").get<double>("H"), 2.0);
  EXPECT_EQ(p->sublist("Blocks").get<int>("Steps"), -7);
}

TEST(ParamTree, KeepsTypesAndNesting) {
  Teuchos::ParameterList l;
  l.set("Method", std::string("Newton"));
  l.sublist("Newton").sublist("Linear Solver").set("Max Iterations", 50);
  l.sublist("Newton").sublist("Linear Solver").set("Tolerance", 1e-7);
  l.set("Flag", true);
  const pf::ParamTree t = pf::treeOf(l, kFile, "Direction");
  using K = pf::ParamTree::Entry::Kind;
  ASSERT_NE(t.find("Method"), nullptr);
  EXPECT_EQ(t.find("Method")->kind, K::String);
  EXPECT_EQ(t.find("Method")->text, "Newton");
  EXPECT_TRUE(t.find("Flag")->flag);
  const pf::ParamTree& ls = *t.find("Newton")->list->find("Linear Solver")->list;
  EXPECT_EQ(ls.find("Max Iterations")->kind, K::Int);
  EXPECT_EQ(ls.find("Max Iterations")->integer, 50);
  EXPECT_EQ(ls.find("Tolerance")->kind, K::Double);
  EXPECT_EQ(ls.find("Tolerance")->number, 1e-7);
}

TEST(SolverRegistry, EveryEntryIsUniqueDocumentedAndBuildsFromItsDefaults) {
  std::vector<std::string> names;
  for (const pf::SolverEntry& e : pf::solverRegistry()) {
    EXPECT_EQ(std::count(names.begin(), names.end(), e.name), 0) << e.name;
    names.push_back(e.name);
    EXPECT_FALSE(e.doc.empty()) << e.name;
    pf::ParameterValues v;
    v.inputFile = kFile;
    v.path = "Solver/" + e.name;
    for (const S& s : e.parameters) {
      EXPECT_FALSE(s.required && !s.defaultValue.empty()) << e.name << ": '" << s.name << "' is required and has a default";
      if (!s.defaultValue.empty()) {
        v.defaults[s.name] = s.defaultValue;
        if (s.kind != S::Kind::Bool && s.kind != S::Kind::String) {
          EXPECT_EQ(s.rangeError(std::strtod(s.defaultValue.c_str(), nullptr)), "") << e.name << ": " << s.name;
        }
      }
      if (s.required) v.values[s.name] = 1.0;
    }
    EXPECT_NE(e.create(v, pf::ParamTree()), nullptr) << e.name;
  }
  for (const char* peridigm : {"Verlet", "QuasiStatic", "NOXQuasiStatic", "Adaptive Dynamic Relaxation"})
    EXPECT_NE(pf::findSolver(peridigm), nullptr) << peridigm;
}

}  // namespace
