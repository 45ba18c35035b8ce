#include "InputSchema.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/Expression.hpp"
#include "core/InfluenceFunction.hpp"
#include "core/InputError.hpp"
#include "core/OutputFields.hpp"

namespace pf {

using PL = Teuchos::ParameterList;

namespace {

enum class T { Double, Int, Bool, String, Scalar /* string or number: YAML may turn "0" into an int */ };

struct P {
  std::string name;
  T type;
  bool required;
};

const char* typeName(T t) {
  switch (t) {
    case T::Double: return "double";
    case T::Int: return "int";
    case T::Bool: return "bool";
    case T::String: return "string";
    case T::Scalar: return "string or number";
  }
  return "?";
}

bool isInt(const Teuchos::ParameterEntry& e) { return e.isType<int>() || e.isType<long long>(); }

bool matches(const Teuchos::ParameterEntry& e, T t) {
  switch (t) {
    case T::Double: return e.isType<double>() || isInt(e);
    case T::Int: return isInt(e);
    case T::Bool: return e.isType<bool>();
    case T::String: return e.isType<std::string>();
    case T::Scalar: return e.isType<std::string>() || e.isType<double>() || isInt(e);
  }
  return false;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& msg) {
  throw InputError(file + ": " + path + ": " + msg);
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

// Rejects unknown entries and wrong types, and reports missing required parameters.
void checkList(const PL& l, const std::string& file, const std::string& path, const std::vector<P>& params,
               const std::vector<std::string>& sublists) {
  for (auto it = l.begin(); it != l.end(); ++it) {
    const std::string& name = l.name(it);
    const Teuchos::ParameterEntry& e = l.entry(it);
    if (e.isList()) {
      if (std::find(sublists.begin(), sublists.end(), name) == sublists.end())
        fail(file, path, "unknown sub-list '" + name + "'" +
                             (sublists.empty() ? std::string() : " (allowed: " + joinNames(sublists) + ")"));
      continue;
    }
    auto p = std::find_if(params.begin(), params.end(), [&](const P& q) { return q.name == name; });
    if (p == params.end()) {
      std::vector<std::string> allowed;
      for (const P& q : params) allowed.push_back(q.name);
      fail(file, path, "unknown parameter '" + name + "'" +
                           (allowed.empty() ? std::string() : " (allowed: " + joinNames(allowed) + ")"));
    }
    if (!matches(e, p->type))
      fail(file, path, "'" + name + "' must be a " + typeName(p->type) + " (got " + e.getAny().typeName() + ")");
  }
  for (const P& q : params)
    if (q.required && !l.isParameter(q.name)) fail(file, path, "missing required parameter '" + q.name + "'");
}

const PL& requireSublist(const PL& l, const std::string& name, const std::string& file, const std::string& path) {
  if (!l.isSublist(name)) fail(file, path, "missing required sub-list '" + name + "'");
  return l.sublist(name);
}

void positive(const PL& l, const std::string& name, const std::string& file, const std::string& path) {
  if (l.isParameter(name) && !(getNumber(l, name) > 0.0))
    fail(file, path, "'" + name + "' must be positive (got " + num(getNumber(l, name)) + ")");
}

void atLeastOne(const PL& l, const std::string& name, const std::string& file, const std::string& path) {
  if (l.isParameter(name) && getInteger(l, name, 1) < 1)
    fail(file, path, "'" + name + "' must be at least 1 (got " + std::to_string(getInteger(l, name, 1)) + ")");
}

void oneOf(const PL& l, const std::string& name, const std::vector<std::string>& values, const std::string& file,
           const std::string& path) {
  if (!l.isParameter(name)) return;
  const std::string v = getText(l, name, "");
  if (std::find(values.begin(), values.end(), v) == values.end())
    fail(file, path, "'" + name + "' = '" + v + "' is not one of " + joinNames(values));
}

// Returns the generated node-set names ("Left Layer", ...) the discretization will provide.
std::set<std::string> validateDiscretization(const PL& d, const std::string& file) {
  const std::string path = "Discretization";
  const std::vector<std::string> types = {"PdQuickGrid", "Text File", "Rectangle With Holes", "Box With Holes"};
  if (!d.isParameter("Type")) fail(file, path, "missing required parameter 'Type'");
  oneOf(d, "Type", types, file, path);
  const std::string type = getText(d, "Type", "");
  std::vector<P> common = {{"Type", T::String, true},
                           {"NeighborhoodType", T::String, false},
                           {"Influence Function", T::String, false},
                           {"Partial Volume", T::Bool, false}};
  std::set<std::string> layers;
  if (type == "PdQuickGrid") {
    checkList(d, file, path, common, {"TensorProduct3DMeshGenerator"});
    const std::string gpath = path + "/TensorProduct3DMeshGenerator";
    const PL& g = requireSublist(d, "TensorProduct3DMeshGenerator", file, path);
    checkList(g, file, gpath,
              {{"Type", T::String, false},
               {"X Origin", T::Double, true}, {"Y Origin", T::Double, true}, {"Z Origin", T::Double, true},
               {"X Length", T::Double, true}, {"Y Length", T::Double, true}, {"Z Length", T::Double, true},
               {"Number Points X", T::Int, true}, {"Number Points Y", T::Int, true},
               {"Number Points Z", T::Int, true}},
              {});
    oneOf(g, "Type", {"PdQuickGrid"}, file, gpath);
    for (const char* a : {"X Length", "Y Length", "Z Length"}) positive(g, a, file, gpath);
    for (const char* a : {"Number Points X", "Number Points Y", "Number Points Z"}) atLeastOne(g, a, file, gpath);
  } else if (type == "Text File") {
    common.push_back({"Input Mesh File", T::String, true});
    checkList(d, file, path, common, {});
    if (d.isParameter("Partial Volume") && d.get<bool>("Partial Volume"))
      fail(file, path, "'Partial Volume' needs a regular grid (PdQuickGrid, Rectangle With Holes, Box With "
                       "Holes): a Text File discretization has no cells to intersect with the horizon");
  } else {
    const bool box = type == "Box With Holes";
    std::vector<P> ps = common;
    for (const P& q : std::vector<P>{{"X Origin", T::Double, false}, {"Y Origin", T::Double, false},
                                     {"X Length", T::Double, true}, {"Y Length", T::Double, true},
                                     {"Spacing", T::Double, true}, {"Grid", T::String, false},
                                     {"Fictitious Layers", T::String, false}, {"Layer Width", T::Double, false}})
      ps.push_back(q);
    if (box) {
      ps.push_back({"Z Origin", T::Double, false});
      ps.push_back({"Z Length", T::Double, true});
    } else {
      ps.push_back({"Thickness", T::Double, true});
    }
    checkList(d, file, path, ps, {"Holes"});
    for (const char* a : {"X Length", "Y Length", "Z Length", "Spacing", "Thickness", "Layer Width"})
      positive(d, a, file, path);
    oneOf(d, "Grid", {"Cell Centers", "Nodes"}, file, path);
    std::vector<std::string> faces = {"Left", "Right", "Bottom", "Top"};
    if (box) faces.insert(faces.end(), {"Back", "Front"});
    for (const std::string& f : splitWords(getText(d, "Fictitious Layers", ""))) {
      if (std::find(faces.begin(), faces.end(), f) == faces.end())
        fail(file, path, "'Fictitious Layers' names unknown face '" + f + "' (faces: " + joinNames(faces) + ")");
      if (!layers.insert(f + " Layer").second)
        fail(file, path, "'Fictitious Layers' names face '" + f + "' twice");
    }
    if (d.isSublist("Holes")) {
      const PL& holes = d.sublist("Holes");
      for (auto it = holes.begin(); it != holes.end(); ++it) {
        const std::string hpath = path + "/Holes/" + holes.name(it);
        if (!holes.entry(it).isList()) fail(file, path + "/Holes", "unknown parameter '" + holes.name(it) +
                                                                     "' (each hole is a sub-list)");
        const PL& h = holes.sublist(holes.name(it));
        std::vector<P> hp = {{"X Center", T::Double, true}, {"Y Center", T::Double, true},
                             {"Radius", T::Double, true}};
        if (box) {
          hp.push_back({"Z Center", T::Double, false});
          hp.push_back({"Axis", T::String, false});
        }
        checkList(h, file, hpath, hp, {});
        positive(h, "Radius", file, hpath);
        if (h.isParameter("Axis")) {
          const std::string a = getText(h, "Axis", "");
          const std::vector<std::string> w = splitWords(a);
          bool ok = a == "x" || a == "y" || a == "z";
          if (!ok && w.size() == 3) {
            ok = true;
            double n2 = 0.0;
            for (const std::string& s : w) {
              try {
                std::size_t used = 0;
                const double c = std::stod(s, &used);
                ok = ok && used == s.size();
                n2 += c * c;
              } catch (const std::exception&) {
                ok = false;
              }
            }
            ok = ok && n2 > 0.0;
          }
          if (!ok) fail(file, hpath, "'Axis' must be x, y, z or three numbers, not all zero (got '" + a + "')");
        }
      }
    }
  }
  oneOf(d, "NeighborhoodType", {"Spherical"}, file, path);
  if (d.isParameter("Influence Function"))
    influenceFromName(getText(d, "Influence Function", ""), file + ": " + path);
  return layers;
}

void validateMaterialsAndBlocks(const PL& p, const std::string& file) {
  const PL& mats = requireSublist(p, "Materials", file, "top level");
  std::vector<std::string> matNames;
  for (auto it = mats.begin(); it != mats.end(); ++it) {
    if (!mats.entry(it).isList())
      fail(file, "Materials", "unknown parameter '" + mats.name(it) + "' (each material is a sub-list)");
    matNames.push_back(mats.name(it));
    materialInputFor(mats.sublist(mats.name(it)), mats.name(it), file);
  }
  if (matNames.empty()) fail(file, "Materials", "no material defined");

  const PL& blocks = requireSublist(p, "Blocks", file, "top level");
  std::set<std::string> seen;
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    const std::string bpath = "Blocks/" + blocks.name(it);
    if (!blocks.entry(it).isList())
      fail(file, "Blocks", "unknown parameter '" + blocks.name(it) + "' (each block group is a sub-list)");
    const PL& b = blocks.sublist(blocks.name(it));
    checkList(b, file, bpath,
              {{"Block Names", T::String, true}, {"Material", T::String, true}, {"Horizon", T::Double, true}}, {});
    const std::string mat = getText(b, "Material", "");
    if (std::find(matNames.begin(), matNames.end(), mat) == matNames.end())
      fail(file, bpath, "'Material' = '" + mat + "' is not defined in Materials (defined: " + joinNames(matNames) +
                            ")");
    positive(b, "Horizon", file, bpath);
    const std::vector<std::string> names = splitWords(getText(b, "Block Names", ""));
    if (names.empty()) fail(file, bpath, "'Block Names' is empty");
    for (const std::string& n : names) {
      // Peridigm's "default": every block of the discretization no other group names (Simulation expands it).
      if (n == "default") {
        if (names.size() != 1) fail(file, bpath, "'Block Names' = 'default' stands alone (no other names with it)");
        if (!seen.insert(n).second) fail(file, bpath, "'Block Names': 'default' is given by two block groups");
        continue;
      }
      bool ok = n.size() > 6 && n.compare(0, 6, "block_") == 0 &&
                n.find_first_not_of("0123456789", 6) == std::string::npos && std::stol(n.substr(6)) >= 1;
      if (!ok) fail(file, bpath, "'Block Names' entry '" + n + "' is not of the form block_<positive integer>");
      if (!seen.insert(n).second) fail(file, bpath, "'Block Names': '" + n + "' is assigned to two block groups");
    }
  }
  if (seen.empty()) fail(file, "Blocks", "no block defined");
}

// Returns the names of all node sets the deck defines (for Reactions).
std::set<std::string> validateBoundaryConditions(const PL& bcs, const std::string& file,
                                                 const std::set<std::string>& generated) {
  const std::string path = "Boundary Conditions";
  std::set<std::string> sets = generated;
  sets.insert("All");
  // Node sets first: a condition may refer to a set defined after it.
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    const std::string& name = bcs.name(it);
    const Teuchos::ParameterEntry& e = bcs.entry(it);
    bool isSet = !e.isList();
    if (e.isList()) {
      const PL& s = bcs.sublist(name);
      isSet = s.isParameter("Type") && s.getEntry("Type").isType<std::string>() &&
              s.get<std::string>("Type") == "Node Set Region";
    }
    if (!isSet) continue;
    if (!e.isList() && !matches(e, T::Scalar))
      fail(file, path, "node set '" + name + "' must be a string of node ids or a file name (got " +
                           e.getAny().typeName() + ")");
    if (!sets.insert(name).second)
      fail(file, path, "node set '" + name + "' clashes with a " +
                           (name == "All" ? std::string("built-in") : std::string("generated")) + " node set");
  }
  const std::vector<std::string> kinds = {"Prescribed Displacement", "Initial Displacement", "Initial Velocity",
                                          "Body Force", "Node Set Region"};
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    if (!bcs.entry(it).isList()) continue;
    const std::string bpath = path + "/" + bcs.name(it);
    const PL& b = bcs.sublist(bcs.name(it));
    if (!b.isParameter("Type")) fail(file, bpath, "missing required parameter 'Type'");
    if (!b.getEntry("Type").isType<std::string>()) fail(file, bpath, "'Type' must be a string");
    oneOf(b, "Type", kinds, file, bpath);
    if (b.get<std::string>("Type") == "Node Set Region") {
      const std::vector<std::string> bounds = {"X Min", "X Max", "Y Min", "Y Max", "Z Min", "Z Max"};
      std::vector<P> ps = {{"Type", T::String, true}, {"Face", T::String, false}, {"Tolerance", T::Double, false}};
      bool anyBound = false;
      for (const std::string& n : bounds) {
        ps.push_back({n, T::Double, false});
        anyBound = anyBound || b.isParameter(n);
      }
      checkList(b, file, bpath, ps, {});
      if (b.isParameter("Face") == anyBound)
        fail(file, bpath, "give either 'Face' or box bounds ('X Min' ... 'Z Max'), not both or neither");
      oneOf(b, "Face", {"Min X", "Max X", "Min Y", "Max Y", "Min Z", "Max Z"}, file, bpath);
      positive(b, "Tolerance", file, bpath);
      if (b.isParameter("Tolerance") && !b.isParameter("Face"))
        fail(file, bpath, "'Tolerance' applies to 'Face' regions only");
      continue;
    }
    checkList(b, file, bpath,
              {{"Type", T::String, true}, {"Node Set", T::String, true}, {"Coordinate", T::String, true},
               {"Value", T::Scalar, true}},
              {});
    const std::string ns = getText(b, "Node Set", "");
    if (!sets.count(ns))
      fail(file, bpath, "'Node Set' = '" + ns + "' is not defined in Boundary Conditions");
    oneOf(b, "Coordinate", {"x", "y", "z"}, file, bpath);
    Expression check(scalarAsText(b.getEntry("Value")), file + ": " + bpath + "/Value");
  }
  return sets;
}

// path: the solver list's name ("Solver", "Solver1", ...).
void validateSolver(const PL& s, const std::string& file, const std::string& path) {
  const std::vector<std::string> solvers = {"Verlet", "Adaptive Dynamic Relaxation", "QuasiStatic", "NOXQuasiStatic"};
  // Peridigm's QuasiStatic may list its load times ("Time Steps") instead of Final Time and a step count.
  const bool timeList = s.isSublist("QuasiStatic") && s.sublist("QuasiStatic").isParameter("Time Steps") &&
                        !s.isParameter("Final Time");
  checkList(s, file, path,
            {{"Verbose", T::Bool, false}, {"Initial Time", T::Double, false}, {"Final Time", T::Double, !timeList}},
            solvers);
  int count = 0;
  for (const std::string& n : solvers) count += s.isSublist(n) ? 1 : 0;
  if (count != 1) fail(file, path, "exactly one solver sub-list is required, one of " + joinNames(solvers));
  if (timeList) {
    const std::string qp = path + "/QuasiStatic";
    const PL& q = s.sublist("QuasiStatic");
    if (!q.getEntry("Time Steps").isType<std::string>()) fail(file, qp, "'Time Steps' must be a string of times");
    if (s.isParameter("Initial Time"))
      fail(file, path, "'Initial Time' with 'Time Steps': the first of the 'Time Steps' is the initial time");
    if (q.isParameter("Number of Load Steps"))
      fail(file, qp, "give 'Time Steps' or 'Number of Load Steps' (with the list's 'Final Time'), not both");
    std::vector<double> times;
    for (const std::string& w : splitWords(q.get<std::string>("Time Steps"))) {
      std::size_t used = 0;
      double t = 0;
      try {
        t = std::stod(w, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != w.size() || !std::isfinite(t)) fail(file, qp, "'Time Steps' entry '" + w + "' is not a number");
      if (!times.empty() && !(t > times.back()))
        fail(file, qp, "'Time Steps' must increase (" + num(t) + " follows " + num(times.back()) + ")");
      times.push_back(t);
    }
    if (times.size() < 2) fail(file, qp, "'Time Steps' needs the initial time and at least one load time");
  } else {
    const double t0 = getNumber(s, "Initial Time", 0.0), t1 = getNumber(s, "Final Time");
    if (!(t1 > t0)) fail(file, path, "'Final Time' (" + num(t1) + ") must exceed 'Initial Time' (" + num(t0) + ")");
  }
  if (s.isSublist("Verlet")) {
    const PL& v = s.sublist("Verlet");
    checkList(v, file, path + "/Verlet", {{"Fixed dt", T::Double, false}, {"Safety Factor", T::Double, false}}, {});
    positive(v, "Fixed dt", file, path + "/Verlet");
    positive(v, "Safety Factor", file, path + "/Verlet");
  }
  if (s.isSublist("Adaptive Dynamic Relaxation")) {
    const std::string ap = path + "/Adaptive Dynamic Relaxation";
    const PL& a = s.sublist("Adaptive Dynamic Relaxation");
    checkList(a, file, ap,
              {{"Number of Load Steps", T::Int, true}, {"Relative Tolerance", T::Double, false},
               {"Absolute Tolerance", T::Double, false}, {"Maximum Iterations", T::Int, false},
               {"Safety Factor", T::Double, false}, {"Verbose", T::Bool, false}},
              {});
    atLeastOne(a, "Number of Load Steps", file, ap);
    atLeastOne(a, "Maximum Iterations", file, ap);
    for (const char* n : {"Relative Tolerance", "Absolute Tolerance", "Safety Factor"}) positive(a, n, file, ap);
  }
  if (s.isSublist("QuasiStatic")) {
    const std::string qp = path + "/QuasiStatic";
    const PL& q = s.sublist("QuasiStatic");
    checkList(q, file, qp,
              {{"Number of Load Steps", T::Int, !timeList}, {"Time Steps", T::String, false},
               {"Absolute Tolerance", T::Double, false}, {"Relative Tolerance", T::Double, false},
               {"Maximum Solver Iterations", T::Int, false}, {"Verbose", T::Bool, false}},
              {});
    atLeastOne(q, "Number of Load Steps", file, qp);
    atLeastOne(q, "Maximum Solver Iterations", file, qp);
    for (const char* n : {"Relative Tolerance", "Absolute Tolerance"}) positive(q, n, file, qp);
  }
  if (s.isSublist("NOXQuasiStatic")) {
    // Periforge's and Peridigm's scalar options are checked here; the NOX sub-lists (Direction, Line
    // Search, Printing, Solver Options) pass through to NOX, which validates its own parameters.
    const std::string np = path + "/NOXQuasiStatic";
    const PL& q = s.sublist("NOXQuasiStatic");
    checkList(q, file, np,
              {{"Number of Load Steps", T::Int, true}, {"Absolute Tolerance", T::Double, false},
               {"Relative Tolerance", T::Double, false}, {"Maximum Solver Iterations", T::Int, false},
               {"Max Solver Iterations", T::Int, false}, {"Maximum Load Step Cuts", T::Int, false},
               {"Verbose", T::Bool, false}, {"Nonlinear Solver", T::String, false},
               {"Preconditioner Bond Radius", T::Double, false}},
              {"Direction", "Line Search", "Printing", "Solver Options"});
    atLeastOne(q, "Number of Load Steps", file, np);
    atLeastOne(q, "Maximum Solver Iterations", file, np);
    atLeastOne(q, "Max Solver Iterations", file, np);
    for (const char* n : {"Relative Tolerance", "Absolute Tolerance"}) positive(q, n, file, np);
  }
}

void checkVariables(const std::vector<std::string>& names, const std::string& file, const std::string& path,
                    const std::string& param) {
  const std::vector<std::string>& known = knownOutputVariables();
  for (const std::string& n : names)
    if (std::find(known.begin(), known.end(), n) == known.end())
      fail(file, path, "'" + param + "' names unknown output variable '" + n + "'");
}

// Splits a comma-separated list, trimming blanks; an empty entry is reported (names may contain spaces).
std::vector<std::string> commaList(const PL& o, const std::string& param, const std::string& file,
                                   const std::string& path) {
  std::stringstream ss(getText(o, param, ""));
  std::string item;
  std::vector<std::string> out;
  while (std::getline(ss, item, ',')) {
    const std::size_t a = item.find_first_not_of(" \t\n"), b = item.find_last_not_of(" \t\n");
    if (a == std::string::npos) fail(file, path, "'" + param + "' has an empty entry");
    out.push_back(item.substr(a, b - a + 1));
  }
  if (out.empty()) fail(file, path, "'" + param + "' is empty");
  return out;
}

// bcs: the deck's Boundary Conditions list, or null if it has none. path: the list's name ("Output",
// "Output1", ...).
void validateOutput(const PL& o, const std::string& file, const std::set<std::string>& nodeSets, const PL* bcs,
                    const std::string& path) {
  checkList(o, file, path,
            {{"Output File Type", T::String, false}, {"Output Format", T::String, false},
             {"Output Filename", T::String, true}, {"Output Frequency", T::Int, false},
             {"Initial Output Step", T::Int, false}, {"Final Output Step", T::Int, false},
             {"Parallel Write", T::Bool, false}, {"Reactions", T::String, false},
             {"Reaction Names", T::String, false}, {"Applied Displacement", T::String, false}},
            {"Output Variables", "Probes"});
  atLeastOne(o, "Initial Output Step", file, path);
  atLeastOne(o, "Final Output Step", file, path);
  if (o.isParameter("Initial Output Step") && o.isParameter("Final Output Step") &&
      getInteger(o, "Final Output Step", 1) + 1 < getInteger(o, "Initial Output Step", 1))
    fail(file, path, "'Final Output Step' + 1 is below 'Initial Output Step': nothing would be written");
  if (o.isParameter("Reaction Names")) {
    if (!o.isParameter("Reactions")) fail(file, path, "'Reaction Names' needs 'Reactions' (one name per entry)");
    const std::vector<std::string> sets = commaList(o, "Reactions", file, path);
    const std::vector<std::string> names = commaList(o, "Reaction Names", file, path);
    if (names.size() != sets.size())
      fail(file, path, "'Reaction Names' has " + std::to_string(names.size()) + " entries, 'Reactions' has " +
                           std::to_string(sets.size()));
    std::set<std::string> seen;
    for (const std::string& n : names)
      if (!seen.insert(n).second) fail(file, path, "'Reaction Names' repeats '" + n + "'");
  }
  if (o.isParameter("Applied Displacement")) {
    const std::string bc = getText(o, "Applied Displacement", "");
    if (!bcs || !bcs->isSublist(bc))
      fail(file, path, "'Applied Displacement' = '" + bc + "' is not a condition of Boundary Conditions");
    const PL& b = bcs->sublist(bc);
    if (getText(b, "Type", "") != "Prescribed Displacement")
      fail(file, path, "'Applied Displacement' = '" + bc + "' is not a Prescribed Displacement");
    Expression e(scalarAsText(b.getEntry("Value")), file + ": Boundary Conditions/" + bc + "/Value");
    if (e.dependsOnSpace())
      fail(file, path, "'Applied Displacement' = '" + bc + "': its Value depends on x, y or z (one value per time is needed)");
  }
  oneOf(o, "Output File Type", {"ExodusII"}, file, path);
  oneOf(o, "Output Format", {"BINARY"}, file, path);
  atLeastOne(o, "Output Frequency", file, path);
  if (o.isParameter("Reactions")) {
    const std::string r = getText(o, "Reactions", "");
    std::stringstream ss(r);
    std::string item;
    bool any = false;
    while (std::getline(ss, item, ',')) {
      const std::size_t a = item.find_first_not_of(" \t"), b = item.find_last_not_of(" \t");
      if (a == std::string::npos) fail(file, path, "'Reactions' has an empty entry");
      item = item.substr(a, b - a + 1);
      if (!nodeSets.count(item)) fail(file, path, "'Reactions' names undefined node set '" + item + "'");
      any = true;
    }
    if (!any) fail(file, path, "'Reactions' is empty");
  }
  if (o.isSublist("Output Variables")) {
    const PL& v = o.sublist("Output Variables");
    // Peridigm fields its regression decks request that Periforge does not compute: named as such
    // rather than as unknown, so the deck's author knows the request was understood.
    for (const char* n : {"Strain_Energy", "Radius", "Neighborhood_Volume"})
      if (v.isParameter(n))
        fail(file, path + "/Output Variables", std::string("Peridigm's output variable '") + n +
                                                   "' is not supported by Periforge");
    std::vector<P> ps;
    for (const std::string& n : knownOutputVariables()) ps.push_back({n, T::Bool, false});
    checkList(v, file, path + "/Output Variables", ps, {});
  }
  if (o.isSublist("Probes")) {
    const PL& probes = o.sublist("Probes");
    for (auto it = probes.begin(); it != probes.end(); ++it) {
      const std::string ppath = path + "/Probes/" + probes.name(it);
      if (!probes.entry(it).isList())
        fail(file, path + "/Probes", "unknown parameter '" + probes.name(it) + "' (each probe is a sub-list)");
      const PL& pr = probes.sublist(probes.name(it));
      checkList(pr, file, ppath,
                {{"X", T::Double, true}, {"Y", T::Double, true}, {"Z", T::Double, false},
                 {"Variables", T::String, true}},
                {});
      const std::vector<std::string> vars = splitWords(getText(pr, "Variables", ""));
      if (vars.empty()) fail(file, ppath, "'Variables' is empty");
      checkVariables(vars, file, ppath, "Variables");
    }
  }
}

}  // namespace

const std::vector<std::string>& knownOutputVariables() {
  // The core's fields, then every registered model's declared outputs (a name may appear in several).
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = coreVectorFields();
    for (const auto* list : {&coreScalarFields(), &globalFields()}) n.insert(n.end(), list->begin(), list->end());
    for (const MaterialEntry& e : materialRegistry())
      for (const std::string& o : e.outputs)
        if (std::find(n.begin(), n.end(), o) == n.end()) n.push_back(o);
    return n;
  }();
  return names;
}

std::vector<std::string> numberedLists(const PL& deck, const std::string& stem) {
  std::vector<std::string> out;
  if (deck.isSublist(stem)) out.push_back(stem);
  std::vector<std::pair<long, std::string>> numbered;
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& n = deck.name(it);
    if (deck.entry(it).isList() && n.size() > stem.size() && n.size() < stem.size() + 10 &&
        n.compare(0, stem.size(), stem) == 0 && n[stem.size()] != '0' &&
        n.find_first_not_of("0123456789", stem.size()) == std::string::npos)
      numbered.push_back({std::stol(n.substr(stem.size())), n});
  }
  std::sort(numbered.begin(), numbered.end());
  for (const auto& e : numbered) out.push_back(e.second);
  return out;
}

double getNumber(const PL& l, const std::string& name, double fallback) {
  if (!l.isParameter(name)) return fallback;
  return getNumber(l, name);
}

double getNumber(const PL& l, const std::string& name) {
  const Teuchos::ParameterEntry& e = l.getEntry(name);
  if (e.isType<double>()) return Teuchos::getValue<double>(e);
  if (e.isType<int>()) return Teuchos::getValue<int>(e);
  if (e.isType<long long>()) return static_cast<double>(Teuchos::getValue<long long>(e));
  throw InputError("'" + name + "' is not a number");
}

int getInteger(const PL& l, const std::string& name, int fallback) {
  if (!l.isParameter(name)) return fallback;
  const Teuchos::ParameterEntry& e = l.getEntry(name);
  if (e.isType<int>()) return Teuchos::getValue<int>(e);
  if (e.isType<long long>()) return static_cast<int>(Teuchos::getValue<long long>(e));
  throw InputError("'" + name + "' is not an integer");
}

std::string getText(const PL& l, const std::string& name, const std::string& fallback) {
  if (!l.isParameter(name)) return fallback;
  return scalarAsText(l.getEntry(name));
}

bool getFlag(const PL& l, const std::string& name, bool fallback) {
  if (!l.isParameter(name)) return fallback;
  return l.get<bool>(name);
}

std::string scalarAsText(const Teuchos::ParameterEntry& e) {
  if (e.isType<std::string>()) return Teuchos::getValue<std::string>(e);
  if (e.isType<int>()) return std::to_string(Teuchos::getValue<int>(e));
  if (e.isType<long long>()) return std::to_string(Teuchos::getValue<long long>(e));
  if (e.isType<double>()) {
    std::ostringstream s;
    s.precision(17);
    s << Teuchos::getValue<double>(e);
    return s.str();
  }
  if (e.isType<bool>()) return Teuchos::getValue<bool>(e) ? "true" : "false";
  throw InputError(std::string("unsupported parameter type ") + e.getAny().typeName());
}

std::vector<std::string> splitWords(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

double maxBlockHorizon(const PL& deck) {
  double h = 0.0;
  if (!deck.isSublist("Blocks")) return h;
  const PL& blocks = deck.sublist("Blocks");
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    if (!blocks.entry(it).isList()) continue;
    const PL& b = blocks.sublist(blocks.name(it));
    if (b.isParameter("Horizon") && matches(b.getEntry("Horizon"), T::Double))
      h = std::max(h, getNumber(b, "Horizon"));
  }
  return h;
}

namespace {

T kindOf(ParameterSpec::Kind k) {
  switch (k) {
    case ParameterSpec::Kind::Double: return T::Double;
    case ParameterSpec::Kind::Int: return T::Int;
    case ParameterSpec::Kind::Bool: return T::Bool;
    case ParameterSpec::Kind::String: return T::String;
    case ParameterSpec::Kind::Scalar: return T::Scalar;
  }
  return T::Scalar;
}

// The range, choices and default a component declared for one of its parameters.
void checkDeclared(const ParameterSpec& s, ParameterValues& in) {
  if (!in.has(s.name)) {
    if (!s.defaultValue.empty()) in.defaults[s.name] = s.defaultValue;
    return;
  }
  if (in.values.count(s.name) && s.kind != ParameterSpec::Kind::Bool) {
    const std::string why = s.rangeError(in.values.at(s.name));
    if (!why.empty()) fail(in.inputFile, in.path, "'" + s.name + "' " + why);
  }
  if (!s.choices.empty() && in.strings.count(s.name) &&
      std::find(s.choices.begin(), s.choices.end(), in.strings.at(s.name)) == s.choices.end())
    fail(in.inputFile, in.path, "'" + s.name + "' = '" + in.strings.at(s.name) + "' is not one of " + joinNames(s.choices));
}

}  // namespace

MaterialInput materialInputFor(const PL& m, const std::string& materialName, const std::string& inputFile) {
  const std::string path = "Materials/" + materialName;
  if (!m.isParameter("Material Model")) fail(inputFile, path, "missing required parameter 'Material Model'");
  if (!m.getEntry("Material Model").isType<std::string>()) fail(inputFile, path, "'Material Model' must be a string");
  const std::string model = m.get<std::string>("Material Model");
  const MaterialEntry* entry = findMaterial(model);
  if (!entry) {
    std::vector<std::string> known;
    for (const MaterialEntry& e : materialRegistry()) known.push_back(e.model);
    fail(inputFile, path, "unknown 'Material Model' = '" + model + "' (known: " + joinNames(known) + ")");
  }
  std::vector<P> ps;
  for (const ParameterSpec& s : entry->parameters) ps.push_back({s.name, kindOf(s.kind), s.required});
  ps.push_back({"Material Model", T::String, true});
  checkList(m, inputFile, path, ps, {});

  MaterialInput in;
  in.name = materialName;
  in.inputFile = inputFile;
  in.path = path;
  for (auto it = m.begin(); it != m.end(); ++it) {
    const std::string& name = m.name(it);
    const Teuchos::ParameterEntry& e = m.entry(it);
    if (e.isType<bool>())
      in.values[name] = Teuchos::getValue<bool>(e) ? 1.0 : 0.0;
    else if (e.isType<std::string>())
      in.strings[name] = Teuchos::getValue<std::string>(e);
    else
      in.values[name] = getNumber(m, name);
  }
  for (const ParameterSpec& s : entry->parameters) checkDeclared(s, in);
  return in;
}

void validateInput(const PL& p, const std::string& inputFile) {
  // Peridigm runs "Solver1", "Solver2", ... in sequence and writes one file per "Output1", "Output2", ...
  // (each checked like "Solver" / "Output" below).
  std::vector<std::string> tops = {"Discretization", "Materials", "Blocks", "Boundary Conditions"};
  const std::vector<std::string> solverLists = numberedLists(p, "Solver"), outputLists = numberedLists(p, "Output");
  for (const std::string& n : solverLists) tops.push_back(n);
  for (const std::string& n : outputLists) tops.push_back(n);
  if (!p.isSublist("Solver")) tops.push_back("Solver");  // so that a missing one is reported as such below
  if (!p.isSublist("Output")) tops.push_back("Output");
  for (auto it = p.begin(); it != p.end(); ++it) {
    const std::string& n = p.name(it);
    for (const std::string stem : {"Solver", "Output"})
      if (p.entry(it).isList() && n.size() > stem.size() && n.compare(0, stem.size(), stem) == 0 &&
          n.find_first_not_of("0123456789", stem.size()) == std::string::npos &&
          (n[stem.size()] == '0' || std::find(tops.begin(), tops.end(), n) == tops.end()))
        fail(inputFile, "top level", "'" + n + "': a numbered " + stem + " list is " + stem +
                                         "<n> with n = 1, 2, ... (no leading zero)");
  }
  checkList(p, inputFile, "top level", {{"Verbose", T::Bool, false}}, tops);
  if (p.isSublist("Solver") && solverLists.size() > 1)
    fail(inputFile, "top level", "give either one 'Solver' list or numbered ones ('" + solverLists[1] +
                                     "', ...), not both");
  if (solverLists.empty()) fail(inputFile, "top level", "missing required sub-list 'Solver' (or 'Solver1', ...)");
  const std::set<std::string> generated =
      validateDiscretization(requireSublist(p, "Discretization", inputFile, "top level"), inputFile);
  validateMaterialsAndBlocks(p, inputFile);
  std::set<std::string> nodeSets = generated;
  if (p.isSublist("Boundary Conditions"))
    nodeSets = validateBoundaryConditions(p.sublist("Boundary Conditions"), inputFile, generated);
  for (const std::string& n : solverLists) validateSolver(p.sublist(n), inputFile, n);
  std::map<std::string, std::string> files;  // Output Filename -> list
  for (const std::string& n : outputLists) {
    validateOutput(p.sublist(n), inputFile, nodeSets,
                   p.isSublist("Boundary Conditions") ? &p.sublist("Boundary Conditions") : nullptr, n);
    const std::string f = getText(p.sublist(n), "Output Filename", "");
    if (files.count(f))
      fail(inputFile, n, "'Output Filename' = '" + f + "' is also the file of '" + files[f] + "'");
    files[f] = n;
  }
  // Layers default to the horizon, so a deck with layers needs a positive width from somewhere.
  const PL& d = p.sublist("Discretization");
  if (!generated.empty() && !d.isParameter("Layer Width") && !(maxBlockHorizon(p) > 0.0))
    fail(inputFile, "Discretization", "'Layer Width' is needed: no block Horizon to default to");
}

}  // namespace pf
