#pragma once
// The list of constitutive models by name ("Material Model" in the input). Each entry declares its
// parameters (validated by the input schema before construction) and how to build the model.
// Adding a model = one file pair in materials/ plus one line in MaterialRegistry.cpp.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "Material.hpp"

namespace pf {

struct ParameterSpec {
  enum class Kind { Double, Bool, String };
  std::string name;
  Kind kind = Kind::Double;
  bool required = false;
  std::string doc;
};

// Validated values of one "Materials" sub-list, converted to plain types (bools as 0/1).
struct MaterialInput {
  std::string name;        // the sub-list name, e.g. "My Steel"
  std::string inputFile;   // for error messages
  std::map<std::string, double> values;
  std::map<std::string, std::string> strings;

  bool has(const std::string& key) const { return values.count(key) != 0; }
  double get(const std::string& key) const;                  // throws InputError if missing
  double get(const std::string& key, double fallback) const;
};

struct MaterialEntry {
  std::string model;                       // "Elastic", "Elastic Plastic", ...
  std::string doc;
  std::vector<ParameterSpec> parameters;
  std::function<std::unique_ptr<Material>(const MaterialInput&)> create;
};

const std::vector<MaterialEntry>& materialRegistry();
const MaterialEntry* findMaterial(const std::string& model);  // nullptr if unknown

// Parameters every OSB solid accepts: density, elastic moduli (any two), planar options, and Peridigm
// options that Periforge accepts but does not need.
std::vector<ParameterSpec> elasticSolidParameters();

}  // namespace pf
