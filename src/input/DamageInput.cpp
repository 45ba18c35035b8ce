// The optional "Damage Models" list -> DamageModelSpecs. Peridigm's one bond-breaking model, "Critical
// Stretch"; a block uses one through its "Damage Model" parameter (BlocksInput.cpp).
#include "Sections.hpp"

namespace pf {

namespace {
using S = ParameterSpec;
const char* const kCriticalStretch = "Critical Stretch";
}  // namespace

std::vector<ParameterSpec> criticalStretchSpecs() {
  return {S::text("Damage Model", "`Critical Stretch` (Peridigm's name; the only model)").need(),
          S::real("Critical Stretch",
                  "s_c: a bond breaks, for good, once (|y_j − y_i| − |ξ|)/|ξ| > s_c (tension only, as Peridigm)")
              .need()
              .positive()};
}

std::vector<DamageModelSpec> parseDamageModels(const PL& deck, const std::string& file) {
  std::vector<DamageModelSpec> out;
  if (!deck.isSublist("Damage Models")) return out;
  const PL& list = deck.sublist("Damage Models");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it), path = "Damage Models/" + name;
    if (!list.entry(it).isList())
      fail(file, "Damage Models", "unknown parameter '" + name + "' (each damage model is a sub-list)");
    const PL& d = list.sublist(name);
    if (!d.isParameter("Damage Model")) fail(file, path, "missing required parameter 'Damage Model'");
    if (!d.getEntry("Damage Model").isType<std::string>()) fail(file, path, "'Damage Model' must be a string");
    const std::string model = d.get<std::string>("Damage Model");
    if (model != kCriticalStretch)
      fail(file, path, "unknown 'Damage Model' = '" + model + "' (known: '" + kCriticalStretch + "')");
    const ParameterValues v = readList(d, criticalStretchSpecs(), {}, file, path);
    out.push_back(DamageModelSpec{name, model, v.get("Critical Stretch")});
  }
  return out;
}

}  // namespace pf
