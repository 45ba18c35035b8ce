// The optional "Damage Models" list -> DamageModelSpecs. Peridigm's bond-breaking models "Critical Stretch",
// "Time Dependent Critical Stretch" (Peridigm_UserDefinedTimeDependentCriticalStretchDamageModel.cpp), "Initial
// Damage" (Peridigm_InitialDamageModel.cpp) and "Interface Aware" (Peridigm_InterfaceAwareDamageModel.cpp; one value
// for every block, ModelBuilder.cpp), and Li & Geng's "Maximum Principal Stress" (seed 003, Eqs. 49-51; correspondence
// models only, ModelBuilder.cpp); a block uses one through its "Damage Model" parameter (BlocksInput.cpp).
#include <cmath>

#include "Sections.hpp"

namespace pf {

namespace {
using S = ParameterSpec;
const char* const kCriticalStretch = "Critical Stretch";
const char* const kMaxPrincipal = "Maximum Principal Stress";
const char* const kTimeDependent = "Time Dependent Critical Stretch";
const char* const kInitialDamage = "Initial Damage";
const char* const kInterfaceAware = "Interface Aware";

ParameterSpec thermalExpansionSpec() {
  return S::real("Thermal Expansion Coefficient",
                 "Peridigm's: the stretch tested is less the thermal strain alpha dT. Periforge always tests the "
                 "stretch less the block material's own thermal strain, so this must equal the material's "
                 "`Thermal Expansion Coefficient` (an input error otherwise)");
}

}  // namespace

std::vector<ParameterSpec> criticalStretchSpecs() {
  return {S::text("Damage Model", "`Critical Stretch` (Peridigm's name)").need(),
          S::real("Critical Stretch",
                  "s_c: a bond breaks, for good, once (|y_j − y_i| − |ξ|)/|ξ| > s_c (tension only, as Peridigm)")
              .need()
              .positive(),
          thermalExpansionSpec()};
}

std::vector<ParameterSpec> interfaceAwareSpecs() {
  return {S::text("Damage Model",
                  "`Interface Aware` (Peridigm's): Critical Stretch with, for a bond between two points, the smaller of "
                  "their blocks' values; Periforge takes decks where every block has an Interface Aware model of one "
                  "value, for which the rule is exactly Critical Stretch's (docs/input.md, \"Damage\")")
              .need(),
          S::real("Critical Stretch", "s_c: a bond breaks, for good, once (|y_j − y_i| − |ξ|)/|ξ| > s_c").need().positive(),
          thermalExpansionSpec()};
}

std::vector<ParameterSpec> timeDependentCriticalStretchSpecs() {
  return {S::text("Damage Model", "`Time Dependent Critical Stretch` (Peridigm's name)").need(),
          S::text("Time Dependent Critical Stretch",
                  "s_c(t): an expression in `t` (Peridigm's RTCompiler language, as a boundary condition's `Value`; "
                  "`value = ` is prepended unless it assigns `value`), evaluated at the time of each force "
                  "evaluation; a bond breaks, for good, once its stretch exceeds s_c(t) then")
              .need(),
          thermalExpansionSpec()};
}

std::vector<ParameterSpec> initialDamageSpecs() {
  return {S::text("Damage Model",
                  "`Initial Damage` (Peridigm's): the bonds crossing its sub-list `Bond Filters` (Discretization's types, "
                  "read once at set-up) start broken; no other bond ever breaks")
              .need()};
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

namespace {

// s_c(t) compiled once; x, y, z are not Peridigm's variables there (its RTC function knows t and value only).
DamageModelSpec timeDependent(const PL& d, const std::string& name, const std::string& file, const std::string& path) {
  const ParameterValues v = readList(d, timeDependentCriticalStretchSpecs(), {}, file, path);
  DamageModelSpec spec{name, kTimeDependent, 0.0, 0.0};
  const std::string where = file + ": " + path + "/Time Dependent Critical Stretch";
  spec.stretchOfTime = std::make_shared<const Expression>(v.text("Time Dependent Critical Stretch"), where);
  if (spec.stretchOfTime->dependsOnSpace())
    fail(file, path + "/Time Dependent Critical Stretch", "a function of t only (x, y, z are not its variables)");
  spec.thermalExpansion = v.get("Thermal Expansion Coefficient", -1.0);
  return spec;
}

}  // namespace

std::vector<DamageModelSpec> parseDamageModels(const PL& deck, const std::string& file, const std::string& dir) {
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
    if (model == kTimeDependent) {
      out.push_back(timeDependent(d, name, file, path));
      continue;
    }
    if (model == kInitialDamage) {
      readList(d, initialDamageSpecs(), {"Bond Filters"}, file, path);
      DamageModelSpec spec{name, model, HUGE_VAL, 0.0};
      spec.initialBreaks = parseBondFilters(requireSublist(d, "Bond Filters", file, path), file, path + "/Bond Filters",
                                            dir, true);
      out.push_back(spec);
      continue;
    }
    if (model != kCriticalStretch && model != kInterfaceAware)
      fail(file, path, "unknown 'Damage Model' = '" + model + "' (known: " +
                           joinNames({kCriticalStretch, kTimeDependent, kInitialDamage, kMaxPrincipal, kInterfaceAware}) +
                           ")");
    const ParameterValues v =
        readList(d, model == kInterfaceAware ? interfaceAwareSpecs() : criticalStretchSpecs(), {}, file, path);
    DamageModelSpec spec{name, model, v.get("Critical Stretch"), 0.0};
    spec.thermalExpansion = v.get("Thermal Expansion Coefficient", -1.0);
    out.push_back(spec);
  }
  return out;
}

}  // namespace pf
