// Peridigm's Data Loader (model/LoadedField.hpp, input/DataLoaderInput.cpp) on hand-made Exodus files whose values
// are known at every time: c_k(t) = (k + 1) t^2 at the file's times 0, 1, 3, so linear interpolation between the
// two times around t (Peridigm's rule) gives (k + 1) t at t in [0, 1] and (k + 1) (4 t - 3) at t in [1, 3], which
// neither the nearest nor the previous time's value nor t^2 itself does.
#include <exodusII.h>

#include <gtest/gtest.h>

#include "input/Deck.hpp"
#include "model/LoadedField.hpp"
#include "test_input_helpers.hpp"

namespace {

const char* kDeck = "deck.xml";

// A file of `nodes` sphere elements on a line with nodal variable `variable` = (k + 1) t^2 at `times`; ids: the node
// ids (empty: 1..nodes).
std::string writeData(const std::string& name, int nodes, const std::vector<double>& times,
                      const std::string& variable = "Conc", std::vector<int> ids = {}) {
  const std::string path = ::testing::TempDir() + name;
  int cpu = sizeof(double), io = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  EXPECT_GE(id, 0);
  ex_put_init(id, "data", 3, nodes, nodes, 1, 0, 0);
  std::vector<double> x(nodes), zero(nodes, 0.0);
  for (int k = 0; k < nodes; ++k) x[k] = k;
  ex_put_coord(id, x.data(), zero.data(), zero.data());
  ex_put_block(id, EX_ELEM_BLOCK, 1, "SPHERE", nodes, 1, 0, 0, 2);
  std::vector<int> conn(nodes);
  for (int k = 0; k < nodes; ++k) conn[k] = k + 1;
  ex_put_conn(id, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr);
  if (ids.empty()) ids = conn;
  ex_put_id_map(id, EX_NODE_MAP, ids.data());
  ex_put_variable_param(id, EX_NODAL, 1);
  const char* names[] = {variable.c_str()};
  ex_put_variable_names(id, EX_NODAL, 1, const_cast<char**>(names));
  for (std::size_t s = 0; s < times.size(); ++s) {
    ex_put_time(id, static_cast<int>(s) + 1, &times[s]);
    std::vector<double> v(nodes);
    for (int k = 0; k < nodes; ++k) v[k] = (k + 1) * times[s] * times[s];
    ex_put_var(id, static_cast<int>(s) + 1, EX_NODAL, 1, 1, nodes, v.data());
  }
  ex_close(id);
  return path;
}

// Piecewise-linear interpolation of (k + 1) t^2 between the times 0, 1, 3.
double expected(int k, double t) { return (k + 1) * (t <= 1.0 ? t : 4.0 * t - 3.0); }

}  // namespace

TEST(LoadedField, InterpolatesLinearlyBetweenTheTwoTimesAroundT) {
  const std::string path = writeData("loaded_linear.e", 4, {0.0, 1.0, 3.0});
  // Owned points 2 and 0 (a rank's share in any order): each gets its own node's values.
  pf::LoadedField field(path, "Conc", kDeck, {2, 0}, 4, {});
  double v[2];
  // Times out of order, so the kept pair of steps is left and re-read; on a file time the value is the file's.
  for (double t : {0.0, 0.5, 1.0, 2.0, 3.0, 0.25, 1.5}) {
    field.valuesAt(t, v);
    // (1 - c) a + c b rounds once per operation on values of at most 27: 1e-14 is round-off's size, not slack.
    EXPECT_NEAR(v[0], expected(2, t), 1e-14) << "t = " << t;
    EXPECT_NEAR(v[1], expected(0, t), 1e-14) << "t = " << t;
  }
}

TEST(LoadedField, AnOvershootOfRoundOffReadsTheEndValue) {
  const std::string path = writeData("loaded_end.e", 2, {0.0, 1.0, 3.0});
  pf::LoadedField field(path, "Conc", kDeck, {0, 1}, 2, {});
  double v[2];
  field.valuesAt(3.0 * (1.0 + 1e-15), v);  // a time summed from steps may pass the last by an ulp or so
  EXPECT_EQ(v[0], 9.0);
  EXPECT_EQ(v[1], 18.0);
}

TEST(LoadedField, BadFilesNameTheDeckTheParameterAndTheFile) {
  const std::string path = writeData("loaded_bad.e", 3, {0.0, 1.0});
  const std::string param = "Data Loader/File Name";
  double v[3];
  EXPECT_INPUT_ERROR(pf::LoadedField(path, "Conc", kDeck, {0, 1, 2}, 4, {}), kDeck, param);  // 3 nodes, 4 points
  EXPECT_INPUT_ERROR(pf::LoadedField(path, "Conc", kDeck, {0, 1, 2}, 3, {1, 2, 7}), path, param);  // ids differ
  EXPECT_INPUT_ERROR(pf::LoadedField(path, "Other", kDeck, {0, 1, 2}, 3, {}), "'Other'", param);
  EXPECT_INPUT_ERROR(pf::LoadedField(path + ".missing", "Conc", kDeck, {0}, 3, {}), ".missing", param);
  pf::LoadedField field(path, "Conc", kDeck, {0, 1, 2}, 3, {});
  EXPECT_INPUT_ERROR(field.valuesAt(1.5, v), path, param);  // after the last time
  const std::string renumbered = writeData("loaded_ids.e", 3, {0.0, 1.0}, "Conc", {5, 6, 7});
  EXPECT_INPUT_ERROR(pf::LoadedField(renumbered, "Conc", kDeck, {0, 1, 2}, 3, {}), "id 5", param);
  EXPECT_NO_THROW(pf::LoadedField(renumbered, "Conc", kDeck, {0, 1, 2}, 3, {5, 6, 7}));  // the points' own ids
}

namespace {

// A QuasiStatic deck over [0, final] with a Data Loader list of `file` and `field`, its field among the outputs.
std::string dataLoaderDeck(const std::string& file, const std::string& field, double final) {
  return R"(<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="PdQuickGrid"/>
    <ParameterList name="TensorProduct3DMeshGenerator">
      <Parameter name="X Origin" type="double" value="0"/><Parameter name="Y Origin" type="double" value="0"/>
      <Parameter name="Z Origin" type="double" value="0"/><Parameter name="X Length" type="double" value="3"/>
      <Parameter name="Y Length" type="double" value="1"/><Parameter name="Z Length" type="double" value="1"/>
      <Parameter name="Number Points X" type="int" value="3"/><Parameter name="Number Points Y" type="int" value="1"/>
      <Parameter name="Number Points Z" type="int" value="1"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials"><ParameterList name="Steel">
    <Parameter name="Material Model" type="string" value="Elastic"/><Parameter name="Density" type="double" value="7800"/>
    <Parameter name="Bulk Modulus" type="double" value="130e9"/><Parameter name="Shear Modulus" type="double" value="78e9"/>
  </ParameterList></ParameterList>
  <ParameterList name="Blocks"><ParameterList name="B">
    <Parameter name="Block Names" type="string" value="block_1"/><Parameter name="Material" type="string" value="Steel"/>
    <Parameter name="Horizon" type="double" value="1.5"/>
  </ParameterList></ParameterList>
  <ParameterList name="Data Loader">
    <Parameter name="File Name" type="string" value=")" + file + R"("/>
    <Parameter name="Field Name" type="string" value=")" + field + R"("/>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value=")" + std::to_string(final) + R"("/>
    <ParameterList name="QuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/></ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="out"/>
    <ParameterList name="Output Variables"><Parameter name=")" + field + R"(" type="bool" value="true"/></ParameterList>
  </ParameterList>
</ParameterList>)";
}

}  // namespace

TEST(DataLoaderInput, ValidDeckGivesItsSpecAndItsFieldIsAnOutput) {
  const std::string path = writeData("loader_deck.e", 3, {0.0, 1.0, 3.0});
  const pf::Deck deck = pf::parseDeck(*pftest::deckFromXml(dataLoaderDeck(path, "Conc", 3.0)), kDeck);
  EXPECT_TRUE(deck.dataLoader.given);
  EXPECT_EQ(deck.dataLoader.file, path);
  EXPECT_EQ(deck.dataLoader.field, "Conc");
  ASSERT_EQ(deck.outputs.size(), 1u);
  EXPECT_EQ(deck.outputs[0].variables, std::vector<std::string>{"Conc"});
}

TEST(DataLoaderInput, BadListsNameTheDeckAndTheParameter) {
  const std::string path = writeData("loader_bad_deck.e", 3, {0.0, 1.0, 3.0});
  auto parse = [](const std::string& xml) { pf::parseDeck(*pftest::deckFromXml(xml), kDeck); };
  EXPECT_INPUT_ERROR(parse(dataLoaderDeck(path, "Absent", 1.0)), kDeck, "Data Loader/Field Name");
  EXPECT_INPUT_ERROR(parse(dataLoaderDeck(path, "Temperature", 1.0)), kDeck, "Data Loader/Field Name");
  EXPECT_INPUT_ERROR(parse(dataLoaderDeck(path, "Conc", 4.0)), "do not cover", "Data Loader/File Name");
  EXPECT_INPUT_ERROR(parse(dataLoaderDeck(path + ".missing", "Conc", 1.0)), ".missing", "Data Loader/File Name");
  const std::string single = writeData("loader_single.e", 3, {0.0});
  EXPECT_INPUT_ERROR(parse(dataLoaderDeck(single, "Conc", 1.0)), "two", "Data Loader/File Name");
}
