#pragma once
// The nodal fields beside the displacement that a material reads in its bond loops (Temperature_Change, ...):
// each a name and one value per overlap node (owned nodes first, then ghosts, as FamilyView's node arrays).
// The model's FieldSet (model/FieldSet.hpp) keeps them current for the state being evaluated; a material names
// what it reads (Material::fieldsRead) and the model refuses a deck that does not provide it.
#include <string>
#include <utility>
#include <vector>

namespace pf {

struct FieldValues {
  std::vector<std::pair<std::string, const double*>> entries;
  // The field's overlap values, or null if this model holds no such field.
  const double* find(const std::string& name) const {
    for (const auto& e : entries)
      if (e.first == name) return e.second;
    return nullptr;
  }
};

}  // namespace pf
