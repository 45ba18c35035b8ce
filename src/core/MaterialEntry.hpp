#pragma once
// The registry's types: what a constitutive model declares about itself (name, parameters, output
// fields) and how it is built. The list itself is materials/MaterialRegistry.cpp; the core and the input
// layer reach it only through materialRegistry(), so nothing below materials/ includes a model.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "FieldOperator.hpp"
#include "Material.hpp"
#include "Parameters.hpp"

namespace pf {

// Validated values of one "Materials" sub-list.
using MaterialInput = ParameterValues;

struct MaterialEntry {
  std::string model;                       // "Elastic", "Elastic Plastic", ...
  std::string doc;
  std::vector<ParameterSpec> parameters;   // besides "Material Model", which every entry takes
  std::function<std::unique_ptr<Material>(const MaterialInput&)> create;
  // Node fields the model can write (the output StateSpecs of its stateSpecs() for some input): the
  // names "Output Variables" and probes may ask for besides the core's own.
  std::vector<std::string> outputs;
  // The terms this entry puts on fields beside the displacement (heat conduction, plastic heating), for the given
  // input; null function or empty result: none. A block's material and operators come from the same "Materials"
  // entry.
  std::function<std::vector<std::unique_ptr<FieldOperator>>(const MaterialInput&)> createOperators = nullptr;
};

const std::vector<MaterialEntry>& materialRegistry();   // defined in materials/MaterialRegistry.cpp
const MaterialEntry* findMaterial(const std::string& model);  // nullptr if unknown

}  // namespace pf
