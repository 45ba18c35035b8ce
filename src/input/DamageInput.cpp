// The optional "Damage Models" list -> DamageModelSpecs. Peridigm's bond-breaking model "Critical Stretch" and
// Li & Geng's "Maximum Principal Stress" (seed 003, Eqs. 49-51; correspondence models only, ModelBuilder.cpp);
// a block uses one through its "Damage Model" parameter (BlocksInput.cpp).
#include "Sections.hpp"

namespace pf {

namespace {
using S = ParameterSpec;
const char* const kCriticalStretch = "Critical Stretch";
const char* const kMaxPrincipal = "Maximum Principal Stress";
}  // namespace

std::vector<ParameterSpec> criticalStretchSpecs() {
  return {S::text("Damage Model", "`Critical Stretch` (Peridigm's name)").need(),
          S::real("Critical Stretch",
                  "s_c: a bond breaks, for good, once (|y_j − y_i| − |ξ|)/|ξ| > s_c (tension only, as Peridigm)")
              .need()
              .positive(),
          S::real("Thermal Expansion Coefficient",
                  "Peridigm's: the stretch tested is less the thermal strain alpha dT. Periforge always tests the "
                  "stretch less the block material's own thermal strain, so this must equal the material's "
                  "`Thermal Expansion Coefficient` (an input error otherwise)")};
}

std::vector<ParameterSpec> maximumPrincipalStressSpecs() {
  return {S::text("Damage Model", "`Maximum Principal Stress` (Li & Geng 2024, Eqs. 49-51; correspondence models only)")
              .need(),
          S::real("Tensile Strength",
                  "f_t [Pa]: a bond breaks, for good, once the mean of its two ends' largest principal Cauchy stress "
                  "exceeds it, (sigma1_i + sigma1_j)/2 > f_t")
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
    if (model == kMaxPrincipal) {
      const ParameterValues v = readList(d, maximumPrincipalStressSpecs(), {}, file, path);
      out.push_back(DamageModelSpec{name, model, 0.0, v.get("Tensile Strength")});
      continue;
    }
    if (model != kCriticalStretch)
      fail(file, path, "unknown 'Damage Model' = '" + model + "' (known: '" + kCriticalStretch + "', '" +
                           kMaxPrincipal + "')");
    const ParameterValues v = readList(d, criticalStretchSpecs(), {}, file, path);
    DamageModelSpec spec{name, model, v.get("Critical Stretch"), 0.0};
    spec.thermalExpansion = v.get("Thermal Expansion Coefficient", -1.0);
    out.push_back(spec);
  }
  return out;
}

}  // namespace pf
