#pragma once
// Shared by test_input*.cpp and test_discretization*.cpp: decks as strings, temp files, error capture.
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include "core/InputError.hpp"

namespace pftest {

inline Teuchos::RCP<Teuchos::ParameterList> deckFromXml(const std::string& xml) {
  return Teuchos::getParametersFromXmlString(xml);
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
