#pragma once
// Shared by test_input*.cpp and test_discretization*.cpp: decks as strings, temp files, error capture.
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include "core/InputError.hpp"
#include "discretization/Discretization.hpp"
#include "discretization/NodeSets.hpp"
#include "input/DeckParser.hpp"
#include "input/Sections.hpp"

namespace pftest {

inline Teuchos::RCP<Teuchos::ParameterList> deckFromXml(const std::string& xml) {
  return Teuchos::getParametersFromXmlString(xml);
}

// The cloud of a Discretization list (defaultLayerWidth: the largest block horizon a deck would give).
inline pf::PointCloud cloudOf(const Teuchos::ParameterList& d, const std::string& file, const std::string& dir,
                              double defaultLayerWidth = 0.0) {
  pf::DiscretizationSpec spec = pf::parseDiscretization(d, file, dir);
  pf::applyDefaultLayerWidth(spec, defaultLayerWidth, file);
  return pf::buildDiscretization(spec, file);
}

// The node sets of a Boundary Conditions list resolved on a cloud.
inline std::map<std::string, std::vector<int>> nodeSetsOf(const Teuchos::ParameterList& bcs, const pf::PointCloud& c,
                                                          const std::string& file, const std::string& dir) {
  std::set<std::string> generated;
  for (const auto& kv : c.generatedNodeSets) generated.insert(kv.first);
  return pf::resolveNodeSets(pf::parseNodeSets(bcs, generated, file, dir), c, file);
}

inline std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << content;
  return path;
}

template <class F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const pf::InputError& e) {
    return e.what();
  }
  return "<no InputError thrown>";
}

// The message must be one line naming the input file and the parameter.
#define EXPECT_INPUT_ERROR(stmt, file, param)                                    \
  do {                                                                           \
    const std::string msg_ = pftest::inputErrorOf([&] { stmt; });                \
    EXPECT_NE(msg_.find(file), std::string::npos) << msg_;                       \
    EXPECT_NE(msg_.find(param), std::string::npos) << msg_;                      \
    EXPECT_EQ(msg_.find('\n'), std::string::npos) << msg_;                       \
  } while (0)

}  // namespace pftest
