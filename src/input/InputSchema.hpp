#pragma once
// Checks one "Materials" sub-list against its model's declared parameters (for tests and tools that
// build a single material from a Teuchos list; readDeck() does the same for a whole deck).
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "core/MaterialEntry.hpp"

namespace pf {

MaterialInput materialInputFor(const Teuchos::ParameterList& materialSublist, const std::string& materialName,
                               const std::string& inputFile);

}  // namespace pf
