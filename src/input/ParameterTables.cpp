#include "ParameterTables.hpp"

#include <sstream>

#include "Sections.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

namespace {

std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string allowed(const ParameterSpec& s) {
  if (!s.choices.empty()) {
    std::string out;
    for (const std::string& c : s.choices) out += (out.empty() ? "`" : ", `") + c + "`";
    return out;
  }
  return s.rangeText();
}

}  // namespace

std::vector<ParameterTable> parameterTables() {
  std::vector<ParameterTable> t = {
      {"discretization", "Discretization (every type)", discretizationSpecs("")},
      {"pdquickgrid", "Discretization/TensorProduct3DMeshGenerator (Type = PdQuickGrid)", quickGridSpecs()},
      {"text-file", "Discretization (Type = Text File), besides the common ones", {}},
      {"exodus", "Discretization (Type = Exodus), besides the common ones", {}},
      {"gmsh", "Discretization (Type = Gmsh), besides the common ones", {}},
      {"rectangle", "Discretization (Type = Rectangle With Holes), besides the common ones", {}},
      {"box", "Discretization (Type = Box With Holes), besides the common ones", {}},
      {"cylinder", "Discretization (Type = Cylinder), besides the common ones", {}},
      {"hole", "Discretization/Holes/<any name> (Rectangle With Holes)", holeSpecs(false)},
      {"hole-box", "Discretization/Holes/<any name> (Box With Holes)", holeSpecs(true)},
      {"bond-filter: Rectangular_Plane", "Discretization/Bond Filters/<any name> with Type = Rectangular_Plane",
       bondFilterSpecs("Rectangular_Plane")},
      {"bond-filter: Disk", "Discretization/Bond Filters/<any name> with Type = Disk", bondFilterSpecs("Disk")},
      {"bond-filter: Exodus Mesh", "Discretization/Bond Filters/<any name> with Type = Exodus Mesh",
       bondFilterSpecs("Exodus Mesh")},
      {"blocks", "Blocks/<any name>", blockSpecs()},
      {"damage: Critical Stretch", "Damage Models/<any name> with Damage Model = Critical Stretch", criticalStretchSpecs()},
      {"damage: Maximum Principal Stress", "Damage Models/<any name> with Damage Model = Maximum Principal Stress",
       maximumPrincipalStressSpecs()},
      {"damage: Time Dependent Critical Stretch",
       "Damage Models/<any name> with Damage Model = Time Dependent Critical Stretch", timeDependentCriticalStretchSpecs()},
      {"damage: Interface Aware", "Damage Models/<any name> with Damage Model = Interface Aware", interfaceAwareSpecs()},
      {"damage: Initial Damage", "Damage Models/<any name> with Damage Model = Initial Damage", initialDamageSpecs()},
      {"node-set-region", "Boundary Conditions/<name> with Type = Node Set Region", regionSpecs()},
      {"condition", "Boundary Conditions/<name> (a condition)", conditionSpecs()},
      {"rigid-wall", "Boundary Conditions/<name> with Type = Rigid Wall", rigidWallSpecs()},
      {"contact", "Contact", contactSpecs()},
      {"contact-model", "Contact/Models/<any name>", contactModelSpecs()},
      {"contact-interaction", "Contact/Interactions/<any name> (a block pair)", contactPairSpecs()},
      {"contact-every", "Contact/Interactions/General Contact and Self Contact", contactEverySpecs()},
      {"solver", "Solver (or Solver1, Solver2, ...)", solverListSpecs()},
      {"output", "Output (or Output1, Output2, ..., or any list whose name contains Output)", outputSpecs()},
      {"probe", "Output/Probes/<any name>", probeSpecs()},
      {"restart", "Restart", restartSpecs()},
      {"data-loader", "Data Loader", dataLoaderSpecs()},
      {"compute", "Compute Class Parameters/<any name>", computeSpecs()}};
  const std::size_t common = discretizationSpecs("").size();
  for (auto& [key, type] : std::vector<std::pair<std::string, std::string>>{
           {"text-file", "Text File"}, {"exodus", "Exodus"}, {"gmsh", "Gmsh"}, {"rectangle", "Rectangle With Holes"}, {"box", "Box With Holes"},
                                             {"cylinder", "Cylinder"}})
    for (ParameterTable& x : t)
      if (x.key == key) {
        const std::vector<ParameterSpec> all = discretizationSpecs(type);
        x.parameters.assign(all.begin() + static_cast<long>(common), all.end());
      }
  for (const MaterialEntry& e : materialRegistry()) t.push_back({"material: " + e.model, "Materials/<name> with Material Model = " + e.model, e.parameters});
  for (const SolverEntry& e : solverRegistry()) t.push_back({"solver: " + e.name, "Solver/" + e.name, e.parameters});
  return t;
}

std::string markdownTable(const std::vector<ParameterSpec>& parameters) {
  std::ostringstream out;
  out << "| parameter | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
  for (const ParameterSpec& s : parameters)
    out << "| `" << s.name << "` | " << kindName(s.kind) << " | "
        << (s.required ? "required" : s.defaultValue.empty() ? "" : "`" + s.defaultValue + "`") << " | "
        << cell(allowed(s)) << " | " << cell(s.doc) << " |\n";
  return out.str();
}

}  // namespace pf
