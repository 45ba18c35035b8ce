// The "Boundary Conditions" list -> NodeSetSpecs (Peridigm's id strings and files, Node Set Regions) and
// ConditionSpecs with their value expressions compiled.
#include <algorithm>
#include <limits>

#include "Input.hpp"
#include "Sections.hpp"
#include "core/Log.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

bool isNodeSetEntry(const PL& bcs, const std::string& name) {
  const Teuchos::ParameterEntry& e = bcs.getEntry(name);
  if (!e.isList()) return true;
  const PL& s = bcs.sublist(name);
  return s.isParameter("Type") && s.getEntry("Type").isType<std::string>() &&
         s.get<std::string>("Type") == "Node Set Region";
}

const char* const kRigidWall = "Rigid Wall";

bool allIntegers(const std::vector<std::string>& words) {
  for (const std::string& w : words)
    if (w.empty() || w.find_first_not_of("0123456789+-") != std::string::npos) return false;
  return !words.empty();
}

NodeSetSpec regionSpec(const PL& r, const std::string& name, const std::string& file) {
  const std::string path = "Boundary Conditions/" + name;
  const ParameterValues v = readList(r, regionSpecs(), {}, file, path);
  const char* bounds[6] = {"X Min", "Y Min", "Z Min", "X Max", "Y Max", "Z Max"};
  bool anyBound = false;
  for (const char* b : bounds) anyBound = anyBound || v.has(b);
  if (v.has("Face") == anyBound)
    fail(file, path, "give either 'Face' or box bounds ('X Min' ... 'Z Max'), not both or neither");
  if (v.has("Tolerance") && !v.has("Face")) fail(file, path, "'Tolerance' applies to 'Face' regions only");
  NodeSetSpec s;
  s.name = name;
  s.kind = NodeSetSpec::Kind::Region;
  if (v.has("Face")) {
    s.face = v.text("Face");
    s.tolerance = v.get("Tolerance", 0.0);
    return s;
  }
  const char* axes[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a) {
    s.lo[a] = v.get(std::string(axes[a]) + " Min", std::numeric_limits<double>::lowest());
    s.hi[a] = v.get(std::string(axes[a]) + " Max", std::numeric_limits<double>::max());
    if (s.lo[a] > s.hi[a]) fail(file, path, std::string("'") + axes[a] + " Min' exceeds '" + axes[a] + " Max'");
  }
  return s;
}

}  // namespace

std::vector<ParameterSpec> regionSpecs() {
  std::vector<ParameterSpec> s = {
      S::text("Type", "`Node Set Region`").need(),
      S::text("Face", "`Min X`, `Max X`, `Min Y`, `Max Y`, `Min Z`, `Max Z`: the points within `Tolerance` of that "
                      "face of the cloud").oneOf({"Min X", "Max X", "Min Y", "Max Y", "Min Z", "Max Z"}),
      S::real("Tolerance", "for `Face`; default: half the grid spacing").positive()};
  for (const char* a : {"X", "Y", "Z"})
    for (const char* m : {" Min", " Max"}) s.push_back(S::real(std::string(a) + m, "inclusive box bound (instead of `Face`)"));
  return s;
}

std::vector<ParameterSpec> conditionSpecs() {
  return {S::text("Type", "`Prescribed Displacement`, `Initial Displacement`, `Initial Velocity`, `Body Force`, "
                          "`Pressure` (on the surface whose outer layer of points is the node set), `Prescribed "
                          "Temperature`, `Initial Temperature`, `Heat Flux`, `Convection` (the Temperature field, "
                          "docs/input.md \"Temperature\"); `Rigid Wall` has its own parameters (below)")
              .need().oneOf({"Prescribed Displacement", "Initial Displacement", "Initial Velocity", "Body Force",
                             "Pressure", "Prescribed Temperature", "Initial Temperature", "Heat Flux", "Convection",
                             "Rigid Wall"}),
          S::text("Node Set", "a node-set name (`All`: every node, unless the deck defines its own `All`)").need(),
          S::text("Coordinate", "`x`, `y` or `z`; required, except for `Pressure` (which acts along the surface's "
                                "normal) and the temperature conditions (a scalar)").oneOf({"x", "y", "z"}),
          S::scalar("Value", "expression in `x`, `y`, `z` (reference coordinates) and `t`; for `Pressure` the "
                             "pressure [Pa], positive pushing on the body; for `Heat Flux` the flux into the body "
                             "[W/m^2]; required except for `Convection`"),
          S::real("Layer Thickness", "`Pressure`, `Heat Flux`, `Convection`: thickness of the surface layer the node "
                                     "set holds; a point of volume V stands for the area V / thickness. Default: the "
                                     "grid spacing")
              .positive(),
          S::flag("Follower", "`Pressure` only: `true` makes it a follower load, acting on the deformed surface "
                              "(traction -p J F^-T N per reference area, as a fluid pressure); needs Blocks "
                              "`Surface Correction` = `NDO Band`. `false`: a dead load on the reference area (-p N)")
              .byDefault("false"),
          S::flag("Apply At Initial Time",
                  "`Prescribed Displacement` only: `false` (Peridigm's increments) leaves the initial state u0 as it "
                  "is (zero, or the `Initial Displacement`) and from the first step on gives u0 + f(t) - f(t0) "
                  "while f(t) differs from f(t0), f(t) where it does not (Peridigm's DirichletIncrementBC); "
                  "`true` (Periforge's) sets f(t) at every time, the initial one included")
              .byDefault("false"),
          S::real("Heat Transfer Coefficient", "`Convection` only: h [W/(m^2 K)] of the heat flow h (T_amb - T) "
                                               "into the surface").positive(),
          S::scalar("Ambient Temperature", "`Convection` only: T_amb [K], an expression in `x`, `y`, `z`, `t`")};
}

std::vector<NodeSetSpec> parseNodeSets(const PL& bcs, const std::set<std::string>& generated, const std::string& file,
                                       const std::string& dir) {
  const std::string path = "Boundary Conditions";
  std::vector<NodeSetSpec> out;
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    const std::string& name = bcs.name(it);
    if (!isNodeSetEntry(bcs, name)) continue;
    const Teuchos::ParameterEntry& e = bcs.entry(it);
    // The deck's own set wins over a built-in ("All") or generated ("Left Layer", ...) set of the same name:
    // Peridigm has no built-in sets, so a Peridigm deck that defines "All" means its own (resolveNodeSets).
    if (name == "All" || generated.count(name))
      warn(file + ": " + path + ": node set '" + name + "' defined by the deck replaces the " +
           (name == "All" ? std::string("built-in set of every node") : std::string("generated set")) +
           " of that name");
    if (e.isList()) {
      out.push_back(regionSpec(bcs.sublist(name), name, file));
      continue;
    }
    if (!(e.isType<std::string>() || e.isType<int>() || e.isType<long long>() || e.isType<double>()))
      fail(file, path, "node set '" + name + "' must be a string of node ids or a file name (got " +
                           e.getAny().typeName() + ")");
    NodeSetSpec s;
    s.name = name;
    s.text = scalarAsText(e);
    if (allIntegers(splitWords(s.text))) {
      s.kind = NodeSetSpec::Kind::Ids;
    } else {
      s.kind = NodeSetSpec::Kind::File;
      s.text = resolvePath(s.text, dir);
    }
    out.push_back(s);
  }
  return out;
}

std::vector<ConditionSpec> parseConditions(const PL& bcs, const std::set<std::string>& nodeSets,
                                           const std::string& file) {
  std::vector<ConditionSpec> out;
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    if (!bcs.entry(it).isList() || isNodeSetEntry(bcs, bcs.name(it))) continue;
    const std::string bpath = "Boundary Conditions/" + bcs.name(it);
    const PL& b = bcs.sublist(bcs.name(it));
    if (!b.isParameter("Type")) fail(file, bpath, "missing required parameter 'Type'");
    if (!b.getEntry("Type").isType<std::string>()) fail(file, bpath, "'Type' must be a string");
    if (b.get<std::string>("Type") == kRigidWall) continue;  // parseRigidWalls
    const ParameterValues v = readList(b, conditionSpecs(), {}, file, bpath);
    ConditionSpec c;
    c.name = bcs.name(it);
    const std::string type = v.text("Type");
    using K = ConditionSpec::Kind;
    c.kind = type == "Prescribed Displacement" ? K::PrescribedDisplacement
             : type == "Initial Displacement"  ? K::InitialDisplacement
             : type == "Initial Velocity"      ? K::InitialVelocity
             : type == "Body Force"            ? K::BodyForce
             : type == "Prescribed Temperature" ? K::PrescribedTemperature
             : type == "Initial Temperature"   ? K::InitialTemperature
             : type == "Heat Flux"             ? K::HeatFlux
             : type == "Convection"            ? K::Convection
                                               : K::Pressure;
    const bool surface = c.kind == K::Pressure || c.kind == K::HeatFlux || c.kind == K::Convection;
    const bool convection = c.kind == K::Convection;
    if (v.has("Layer Thickness") && !surface)
      fail(file, bpath, "'Layer Thickness' applies to a Pressure, Heat Flux or Convection only");
    if (v.flag("Follower") && c.kind != K::Pressure) fail(file, bpath, "'Follower' applies to a Pressure only");
    if (b.isParameter("Apply At Initial Time") && c.kind != K::PrescribedDisplacement)
      fail(file, bpath, "'Apply At Initial Time' applies to a Prescribed Displacement only");
    c.atInitialTime = v.flag("Apply At Initial Time");
    for (const char* n : {"Heat Transfer Coefficient", "Ambient Temperature"}) {
      if (v.has(n) && !convection) fail(file, bpath, std::string("'") + n + "' applies to a Convection only");
      if (!v.has(n) && convection) fail(file, bpath, std::string("missing required parameter '") + n + "'");
    }
    if (convection && v.has("Value")) fail(file, bpath, "'Value' does not apply to a Convection (give 'Ambient Temperature')");
    if (!convection && !v.has("Value")) fail(file, bpath, "missing required parameter 'Value'");
    const bool scalar = c.kind == K::PrescribedTemperature || c.kind == K::InitialTemperature || c.kind == K::HeatFlux ||
                        convection;
    if (c.kind == K::Pressure) {
      if (v.has("Coordinate")) fail(file, bpath, "'Coordinate' does not apply to a Pressure (it acts along the normal)");
      c.follower = v.flag("Follower");
    } else if (scalar) {
      if (v.has("Coordinate")) fail(file, bpath, "'Coordinate' does not apply to a " + type + " (a scalar field)");
    } else {
      if (!v.has("Coordinate")) fail(file, bpath, "missing required parameter 'Coordinate'");
      c.coordinate = v.text("Coordinate")[0] - 'x';
    }
    c.layerThickness = v.get("Layer Thickness", 0.0);
    c.transferCoefficient = v.get("Heat Transfer Coefficient", 0.0);
    c.nodeSet = v.text("Node Set");
    if (!nodeSets.count(c.nodeSet))
      fail(file, bpath, "'Node Set' = '" + c.nodeSet + "' is not defined in Boundary Conditions");
    const std::string valueName = convection ? "Ambient Temperature" : "Value";
    c.value = std::make_shared<const Expression>(v.text(valueName), file + ": " + bpath + "/" + valueName);
    out.push_back(c);
  }
  return out;
}

}  // namespace pf
