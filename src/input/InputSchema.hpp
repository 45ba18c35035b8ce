#pragma once
// The one place the input deck is validated. validateInput() rejects, with a one-line InputError that
// names the file and the parameter path, every unknown parameter or sub-list, every missing required
// one, every wrong type and every out-of-range value it can judge without reading other files.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/MaterialEntry.hpp"

namespace pf {

void validateInput(const Teuchos::ParameterList& p, const std::string& inputFile);

// One "Materials" sub-list checked against the model's ParameterSpecs (materialRegistry()).
MaterialInput materialInputFor(const Teuchos::ParameterList& materialSublist, const std::string& materialName,
                               const std::string& inputFile);

// Largest "Horizon" over the Blocks list of a deck (0 if none): the default fictitious-layer width.
double maxBlockHorizon(const Teuchos::ParameterList& deck);

// Output variable names accepted in "Output Variables" and in probe "Variables".
const std::vector<std::string>& knownOutputVariables();

// The top-level lists named stem ("Solver", "Output"): the plain one if present, then Peridigm's numbered
// stem1, stem2, ... in increasing number. Validated by validateInput (a deck gives "Solver" or numbered
// solver lists, not both).
std::vector<std::string> numberedLists(const Teuchos::ParameterList& deck, const std::string& stem);

// Typed access for code that runs after validation. Numbers written as int where a double is expected
// (common in YAML) are accepted.
double getNumber(const Teuchos::ParameterList& l, const std::string& name, double fallback);
double getNumber(const Teuchos::ParameterList& l, const std::string& name);
int getInteger(const Teuchos::ParameterList& l, const std::string& name, int fallback);
std::string getText(const Teuchos::ParameterList& l, const std::string& name, const std::string& fallback);
bool getFlag(const Teuchos::ParameterList& l, const std::string& name, bool fallback);
// A parameter as text whatever its scalar type (YAML turns "0.0" or "7" into numbers).
std::string scalarAsText(const Teuchos::ParameterEntry& e);

// Splits on whitespace and commas.
std::vector<std::string> splitWords(const std::string& s);

}  // namespace pf
