#include "MaterialEntry.hpp"

namespace pf {

const MaterialEntry* findMaterial(const std::string& model) {
  for (const MaterialEntry& e : materialRegistry())
    if (e.model == model) return &e;
  return nullptr;
}

}  // namespace pf
