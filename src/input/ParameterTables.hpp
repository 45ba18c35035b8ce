#pragma once
// Every list a deck may hold with the parameters its owner declares (the input layer's own lists, every
// material and solver in the registries): the source of docs/input.md's tables
// (scripts/generate_input_docs, checked current by ctest).
#include <string>
#include <vector>

#include "core/Parameters.hpp"

namespace pf {

struct ParameterTable {
  std::string key;    // stable name of the table, e.g. "blocks", "material: Elastic", "solver: Verlet"
  std::string title;  // where the list sits in a deck
  std::vector<ParameterSpec> parameters;
};

std::vector<ParameterTable> parameterTables();

// A Markdown table: parameter, type, default (or "required"), allowed values or range, meaning.
std::string markdownTable(const std::vector<ParameterSpec>& parameters);

}  // namespace pf
