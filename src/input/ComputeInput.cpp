// Peridigm's "Compute Class Parameters" list -> ComputeSpecs (the compute classes Block_Data, Node_Set_Data and
// Nearest_Point_Data, with Peridigm's parameter names and meanings).
#include <algorithm>
#include <set>

#include "Sections.hpp"
#include "core/OutputFields.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

// Peridigm's compute classes that Periforge does not have: named as such, so a deck's author sees the request
// was understood.
const std::vector<std::string> kUnsupported = {"JIntegral", "Kinetic_Energy", "Strain_Energy", "Angular_Momentum",
                                                "Linear_Momentum", "Energy"};

}  // namespace

std::vector<ParameterSpec> computeSpecs() {
  return {S::text("Compute Class", "`Block_Data`: reduce `Variable` over the points of `Block`; `Node_Set_Data`: "
                                   "over those of `Node Set`; `Nearest_Point_Data`: its value at the point nearest to "
                                   "(`X`, `Y`, `Z`)")
              .need(),
          S::text("Calculation Type", "`Sum`, `Minimum` or `Maximum` (Block_Data, Node_Set_Data; per component)")
              .oneOf({"Sum", "Minimum", "Maximum"}),
          S::text("Block", "Block_Data: `block_N`"),
          S::text("Node Set", "Node_Set_Data: a node set of the deck or of the mesh"),
          S::real("X", "Nearest_Point_Data: position (reference configuration)"),
          S::real("Y", ""),
          S::real("Z", ""),
          S::text("Variable", "an output variable (a vector gives three globals, `<Output Label>X/Y/Z`)").need(),
          S::text("Output Label", "the global output's name, which `Output Variables` lists to write it").need()};
}

std::vector<ComputeSpec> parseComputes(const PL& list, const std::set<std::string>& nodeSets, const std::string& file) {
  const std::string path = "Compute Class Parameters";
  const std::vector<std::string>& known = knownOutputVariables();
  const std::vector<std::string>& globals = globalFields();
  std::vector<ComputeSpec> out;
  std::set<std::string> labels;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string cpath = path + "/" + list.name(it);
    if (!list.entry(it).isList()) fail(file, path, "unknown parameter '" + list.name(it) + "' (each compute is a sub-list)");
    const PL& sub = list.sublist(list.name(it));
    if (sub.isParameter("Compute Class")) {
      const std::string cls = getText(sub, "Compute Class", "");
      for (const std::string& u : kUnsupported)
        if (cls == u) fail(file, cpath, "Peridigm's compute class '" + cls + "' is not supported by Periforge");
    }
    const ParameterValues v = readList(sub, computeSpecs(), {}, file, cpath);
    ComputeSpec c;
    c.name = list.name(it);
    const std::string cls = v.text("Compute Class");
    const bool point = cls == "Nearest_Point_Data";
    if (cls == "Block_Data") c.kind = ComputeSpec::Kind::BlockData;
    else if (cls == "Node_Set_Data") c.kind = ComputeSpec::Kind::NodeSetData;
    else if (point) c.kind = ComputeSpec::Kind::NearestPointData;
    else fail(file, cpath, "'Compute Class' = '" + cls + "' is not one of 'Block_Data', 'Node_Set_Data', 'Nearest_Point_Data'");
    auto only = [&](const char* p, bool allowed) {
      if (v.has(p) && !allowed) fail(file, cpath, std::string("'") + p + "' does not belong to Compute Class '" + cls + "'");
      if (!v.has(p) && allowed) fail(file, cpath, std::string("Compute Class '") + cls + "' needs '" + p + "'");
    };
    only("Calculation Type", !point);
    only("Block", c.kind == ComputeSpec::Kind::BlockData);
    only("Node Set", c.kind == ComputeSpec::Kind::NodeSetData);
    for (const char* a : {"X", "Y", "Z"}) only(a, point);
    if (!point) {
      const std::string t = v.text("Calculation Type");
      c.calculation = t == "Sum" ? ComputeSpec::Calculation::Sum
                      : t == "Minimum" ? ComputeSpec::Calculation::Minimum : ComputeSpec::Calculation::Maximum;
    }
    if (c.kind == ComputeSpec::Kind::BlockData) {
      c.block = blockNumber(v.text("Block"));
      if (c.block == 0) fail(file, cpath, "'Block' = '" + v.text("Block") + "' is not of the form block_<positive integer>");
    }
    if (c.kind == ComputeSpec::Kind::NodeSetData) {
      c.nodeSet = v.text("Node Set");
      if (!nodeSets.count(c.nodeSet)) fail(file, cpath, "'Node Set' = '" + c.nodeSet + "' is not a node set of the deck or the mesh");
    }
    if (point) c.at = {v.get("X"), v.get("Y"), v.get("Z")};
    c.variable = v.text("Variable");
    if (std::find(known.begin(), known.end(), c.variable) == known.end() ||
        std::find(globals.begin(), globals.end(), c.variable) != globals.end())
      fail(file, cpath, "'Variable' = '" + c.variable + "' is not a per-point output variable");
    c.label = v.text("Output Label");
    if (std::find(known.begin(), known.end(), c.label) != known.end())
      fail(file, cpath, "'Output Label' = '" + c.label + "' is the name of an output variable");
    if (!labels.insert(c.label).second) fail(file, cpath, "'Output Label' = '" + c.label + "' is used by another compute");
    out.push_back(c);
  }
  return out;
}

}  // namespace pf
