// The "Discretization" list -> DiscretizationSpec.
#include <cmath>

#include "ExodusFile.hpp"
#include "GmshFile.hpp"
#include "Input.hpp"
#include "Sections.hpp"

namespace pf {

namespace {

using S = ParameterSpec;
const std::vector<std::string> kTypes = {"PdQuickGrid", "Text File", "Rectangle With Holes", "Box With Holes",
                                         "Cylinder", "Exodus", "Gmsh"};

// "x", "y", "z" or three numbers, not all zero -> a unit vector.
std::array<double, 3> holeAxis(const std::string& a, const std::string& file, const std::string& path) {
  if (a == "x") return {1.0, 0.0, 0.0};
  if (a == "y") return {0.0, 1.0, 0.0};
  if (a == "z") return {0.0, 0.0, 1.0};
  const std::vector<std::string> w = splitWords(a);
  std::array<double, 3> axis{};
  double n2 = 0.0;
  bool ok = w.size() == 3;
  for (int k = 0; ok && k < 3; ++k) {
    try {
      std::size_t used = 0;
      axis[k] = std::stod(w[k], &used);
      ok = used == w[k].size();
      n2 += axis[k] * axis[k];
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || !(n2 > 0.0)) fail(file, path, "'Axis' must be x, y, z or three numbers, not all zero (got '" + a + "')");
  for (double& v : axis) v /= std::sqrt(n2);
  return axis;
}

std::vector<HoleSpec> parseHoles(const PL& holes, bool box, const std::string& file) {
  std::vector<HoleSpec> out;
  for (auto it = holes.begin(); it != holes.end(); ++it) {
    const std::string hpath = "Discretization/Holes/" + holes.name(it);
    if (!holes.entry(it).isList())
      fail(file, "Discretization/Holes", "unknown parameter '" + holes.name(it) + "' (each hole is a sub-list)");
    const ParameterValues h = readList(holes.sublist(holes.name(it)), holeSpecs(box), {}, file, hpath);
    HoleSpec hole;
    hole.centre = {h.get("X Center"), h.get("Y Center"), box ? h.get("Z Center") : 0.0};
    hole.radius = h.get("Radius");
    hole.axis = box ? holeAxis(h.text("Axis"), file, hpath) : std::array<double, 3>{0.0, 0.0, 1.0};
    out.push_back(hole);
  }
  return out;
}

// v: the list's values, read against discretizationSpecs of the generator's type.
void parseGenerator(const PL& d, const ParameterValues& v, DiscretizationSpec& s, const std::string& file) {
  const bool box = s.type == DiscretizationSpec::Type::BoxWithHoles;
  const char* ax[3] = {"X", "Y", "Z"};
  for (int a = 0; a < (box ? 3 : 2); ++a) {
    s.origin[a] = v.get(std::string(ax[a]) + " Origin");
    s.length[a] = v.get(std::string(ax[a]) + " Length");
  }
  s.spacing = v.get("Spacing");
  s.gridNodes = v.text("Grid") == "Nodes";
  if (!box) s.thickness = v.get("Thickness");
  s.layerWidth = v.get("Layer Width", 0.0);
  std::vector<std::string> faces = {"Left", "Right", "Bottom", "Top"};
  if (box) faces.insert(faces.end(), {"Back", "Front"});
  for (const std::string& f : splitWords(v.has("Fictitious Layers") ? v.text("Fictitious Layers") : "")) {
    if (std::find(faces.begin(), faces.end(), f) == faces.end())
      fail(file, "Discretization", "'Fictitious Layers' names unknown face '" + f + "' (faces: " + joinNames(faces) + ")");
    if (std::find(s.layers.begin(), s.layers.end(), f) != s.layers.end())
      fail(file, "Discretization", "'Fictitious Layers' names face '" + f + "' twice");
    s.layers.push_back(f);
  }
  if (d.isSublist("Holes")) s.holes = parseHoles(d.sublist("Holes"), box, file);
}

}  // namespace

std::vector<ParameterSpec> discretizationSpecs(const std::string& type) {
  std::vector<ParameterSpec> s = {
      S::text("Type", "how the points are made (sections below)").need().oneOf(kTypes),
      S::text("NeighborhoodType",
              "Peridigm's; `Spherical`: neighbours within δ. PdQuickGrid without it (Peridigm's default): every "
              "point within round(δ/dx) cells in each direction, a box, unless `Partial Volume`; other types: "
              "always spherical").oneOf({"Spherical"}),
      S::text("Influence Function",
              "`One`, `Parabolic Decay`, `Gaussian`, or an expression in `zeta` and `horizon`").byDefault("One"),
      S::flag("Partial Volume",
              "`false`: Peridigm's rule, a neighbour counts whole if its centre is within δ; `true`: every "
              "neighbour whose grid cell overlaps the horizon ball counts with the share of its cell inside it "
              "(regular grids only)").byDefault("false"),
      S::text("Omit Bonds Between Blocks", "Peridigm's: `All`, no bond joins points of two different blocks; `None`: "
                                           "bonds cross block boundaries").byDefault("None").oneOf({"All", "None"})};
  if (type == "Text File")
    s.push_back(S::text("Input Mesh File", "file of lines `x y z block_id volume`; `#` starts a comment").need());
  if (type == "Exodus")
    s.push_back(S::text("Input Mesh File", "Exodus II genesis file: one point per element at its centroid with its "
                                           "volume; blocks `block_<id>`; the file's node sets by name").need());
  if (type == "Gmsh")
    s.push_back(S::text("Input Mesh File", "Gmsh MSH 4.1 file (ASCII or binary): one point per element of its "
                                           "highest dimension at its centroid with its volume; blocks `block_<tag>` "
                                           "of the physical groups of that dimension (a physical name is an alias); "
                                           "a lower-dimension physical group is a node set, by its physical name or "
                                           "`nodelist_<tag>`").need());
  if (type == "Exodus")
    s.push_back(S::flag("Construct Interfaces", "Peridigm's: write `Interfaces.e` in the working directory, one QUAD4 "
                                                "or TRI3 element per face two bonded elements share (HEX8 and TET4 "
                                                "meshes), with their `interface_aperture` at each output of the "
                                                "first output list").byDefault("false"));
  if (type == "Exodus" || type == "Gmsh")
    s.push_back(S::real("Thickness", "out-of-plane thickness of a mesh of 2D elements (QUAD, TRI): volume = area·"
                                     "Thickness").positive());
  if (type == "Rectangle With Holes" || type == "Box With Holes") {
    const bool box = type == "Box With Holes";
    for (const char* a : {"X", "Y", "Z"}) {
      if (!box && std::string(a) == "Z") break;
      s.push_back(S::real(std::string(a) + " Origin", "lower corner").byDefault("0"));
      s.push_back(S::real(std::string(a) + " Length", "size; a multiple of `Spacing`").need().positive());
    }
    s.push_back(S::real("Spacing", "grid spacing Δx (the same in every direction)").need().positive());
    if (!box) s.push_back(S::real("Thickness", "out-of-plane thickness; volume = Δx²·Thickness").need().positive());
    s.push_back(S::text("Grid", "`Cell Centers`: N = L/Δx points at cell centres; `Nodes`: N + 1 points at x0 + iΔx")
                    .byDefault("Cell Centers").oneOf({"Cell Centers", "Nodes"}));
    s.push_back(S::text("Fictitious Layers",
                        std::string("faces that get a layer outside them, space- or comma-separated: `Left` (min x), "
                                    "`Right`, `Bottom` (min y), `Top`") + (box ? ", `Back` (min z), `Front`" : "")));
    s.push_back(S::real("Layer Width", "layer width; default: the largest `Horizon` in `Blocks`").positive());
  }
  if (type == "Cylinder") {
    for (const char* a : {"X", "Y", "Z"})
      s.push_back(S::real(std::string(a) + " Center", "centre of the base face (the end at the lowest axis coordinate)")
                      .byDefault("0"));
    s.push_back(S::text("Axis", "the cylinder's axis: `x`, `y` or `z` (a lattice direction)").byDefault("z")
                    .oneOf({"x", "y", "z"}));
    s.push_back(S::real("Radius", "radius R; the diameter 2R a multiple of `Spacing`").need().positive());
    s.push_back(S::real("Length", "length along the axis; a multiple of `Spacing`").need().positive());
    s.push_back(S::real("Spacing", "lattice spacing Δx: 2R/Δx points across the diameter").need().positive());
  }
  return s;
}

std::vector<ParameterSpec> quickGridSpecs() {
  std::vector<ParameterSpec> s = {S::text("Type", "`PdQuickGrid` (Peridigm's)").oneOf({"PdQuickGrid"})};
  for (const char* a : {"X", "Y", "Z"}) s.push_back(S::real(std::string(a) + " Origin", "corner of the box").need());
  for (const char* a : {"X", "Y", "Z"}) s.push_back(S::real(std::string(a) + " Length", "box size").need().positive());
  for (const char* a : {"X", "Y", "Z"})
    s.push_back(S::integer(std::string("Number Points ") + a, "cells per direction").need().atLeast(1));
  return s;
}

std::vector<ParameterSpec> holeSpecs(bool box) {
  std::vector<ParameterSpec> s = {S::real("X Center", "hole axis position").need(), S::real("Y Center", "").need(),
                                  S::real("Radius", "hole radius").need().positive()};
  if (box) {
    s.push_back(S::real("Z Center", "").byDefault("0"));
    s.push_back(S::text("Axis", "`x`, `y`, `z` or three numbers (a direction)").byDefault("z"));
  }
  return s;
}

namespace {

// A generated lattice placed so far from zero that neighbouring points round to the same coordinates would
// surface later as "two points with the same coordinates", naming no parameter: refused here. Double
// precision holds about 15.9 digits; the spacing must stay above 1e-12 of the coordinates' magnitude so
// that bond vectors keep at least three correct digits.
void requireResolvableGrid(const DiscretizationSpec& s, const std::string& file, const std::string& path) {
  using T = DiscretizationSpec::Type;
  if (s.type == T::TextFile || s.isElementMesh()) return;
  const char* names[3][2] = {{"X Origin", "X Center"}, {"Y Origin", "Y Center"}, {"Z Origin", "Z Center"}};
  for (int a = 0; a < 3; ++a) {
    const double extent = s.type == T::Cylinder ? s.cylinderLength + s.radius : s.length[a];
    const double spacing = s.type == T::QuickGrid ? s.length[a] / std::max(1, s.count[a]) : s.spacing;
    const double magnitude = std::fabs(s.origin[a]) + extent;
    if (spacing > 1e-12 * magnitude) continue;
    fail(file, path, "'" + std::string(names[a][s.type == T::Cylinder]) + "' = " + numberText(s.origin[a]) +
                         " puts the points so far from zero that their spacing " + numberText(spacing) +
                         " is below double precision's resolution there (keep coordinates within 1e12 spacings of zero)");
  }
}

// An element mesh's header only: the node-set names for the conditions to name, the element count and (Gmsh) the
// block names.
void readMeshNames(DiscretizationSpec& s, const std::string& file, const std::string& path) {
  if (s.type == DiscretizationSpec::Type::Exodus) {
    const ExodusFile mesh(s.meshFile, file);
    for (const ExodusNodeSet& n : mesh.summary().nodeSets)
      if (n.nodes > 0) s.meshNodeSets.push_back(n.name);  // an empty set names no element (the reader skips it)
    s.meshElements = mesh.summary().elements;
  } else {
    const GmshFile mesh(s.meshFile, file);
    for (const GmshNodeSet& n : mesh.summary().nodeSets) s.meshNodeSets.push_back(n.name);
    s.meshElements = mesh.summary().elements;
    s.meshBlockNames = mesh.summary().blockNames;
  }
  if (s.meshNodeSets.size() > 50)  // the point exchange carries set membership as bits of one double
    fail(file, path + "/Input Mesh File", "the mesh '" + s.meshFile + "' has " + std::to_string(s.meshNodeSets.size()) +
                                              " non-empty node sets; Periforge reads at most 50");
}

}  // namespace

DiscretizationSpec parseDiscretization(const PL& d, const std::string& file, const std::string& dir) {
  const std::string path = "Discretization";
  if (!d.isParameter("Type")) fail(file, path, "missing required parameter 'Type'");
  const std::string type = getText(d, "Type", "");
  if (std::find(kTypes.begin(), kTypes.end(), type) == kTypes.end())
    fail(file, path, "'Type' = '" + type + "' is not one of " + joinNames(kTypes));
  std::vector<std::string> sublists = {"Bond Filters"};
  if (type == "PdQuickGrid") sublists.push_back("TensorProduct3DMeshGenerator");
  if (type == "Rectangle With Holes" || type == "Box With Holes") sublists.push_back("Holes");
  const ParameterValues v = readList(d, discretizationSpecs(type), sublists, file, path);
  DiscretizationSpec s;
  if (type == "PdQuickGrid") {
    s.type = DiscretizationSpec::Type::QuickGrid;
    const ParameterValues g = readList(requireSublist(d, "TensorProduct3DMeshGenerator", file, path), quickGridSpecs(),
                                       {}, file, path + "/TensorProduct3DMeshGenerator");
    const char* ax[3] = {"X", "Y", "Z"};
    for (int a = 0; a < 3; ++a) {
      s.origin[a] = g.get(std::string(ax[a]) + " Origin");
      s.length[a] = g.get(std::string(ax[a]) + " Length");
      s.count[a] = static_cast<int>(g.get(std::string("Number Points ") + ax[a]));
    }
  } else if (type == "Cylinder") {
    s.type = DiscretizationSpec::Type::Cylinder;
    s.origin = {v.get("X Center"), v.get("Y Center"), v.get("Z Center")};
    s.cylinderAxis = v.text("Axis")[0] - 'x';
    s.radius = v.get("Radius");
    s.cylinderLength = v.get("Length");
    s.spacing = v.get("Spacing");
  } else if (type == "Text File") {
    s.type = DiscretizationSpec::Type::TextFile;
    s.meshFile = resolvePath(v.text("Input Mesh File"), dir);
  } else if (type == "Exodus" || type == "Gmsh") {
    s.type = type == "Exodus" ? DiscretizationSpec::Type::Exodus : DiscretizationSpec::Type::Gmsh;
    s.meshFile = resolvePath(v.text("Input Mesh File"), dir);
    s.thickness = v.get("Thickness", 0.0);
    s.constructInterfaces = s.type == DiscretizationSpec::Type::Exodus && v.flag("Construct Interfaces");
    readMeshNames(s, file, path);
  } else {
    s.type = type == "Box With Holes" ? DiscretizationSpec::Type::BoxWithHoles
                                      : DiscretizationSpec::Type::RectangleWithHoles;
    parseGenerator(d, v, s, file);
  }
  requireResolvableGrid(s, file, path + (s.type == DiscretizationSpec::Type::QuickGrid ? "/TensorProduct3DMeshGenerator" : ""));
  s.influence = influenceFromName(v.text("Influence Function"), file + ": " + path);
  s.partialVolume = v.flag("Partial Volume");
  s.omitBondsBetweenBlocks = v.text("Omit Bonds Between Blocks") == "All";
  if (d.isSublist("Bond Filters"))
    s.bondFilters = parseBondFilters(d.sublist("Bond Filters"), file, path + "/Bond Filters", dir, false);
  s.boxNeighbourhood = s.type == DiscretizationSpec::Type::QuickGrid && !v.has("NeighborhoodType") && !s.partialVolume;
  if (s.partialVolume && (s.type == DiscretizationSpec::Type::TextFile || s.isElementMesh()))
    fail(file, path, "'Partial Volume' needs a regular grid (PdQuickGrid, Rectangle With Holes, Box With "
                     "Holes): a " + type + " discretization has no cells to intersect with the horizon");
  return s;
}

void applyDefaultLayerWidth(DiscretizationSpec& d, double maxHorizon, const std::string& file) {
  if (d.layers.empty() || d.layerWidth > 0.0) return;
  d.layerWidth = maxHorizon;
  if (!(d.layerWidth > 0.0)) fail(file, "Discretization", "'Layer Width' is needed: no block Horizon to default to");
}

std::vector<std::string> generatedNodeSetNames(const DiscretizationSpec& d) {
  std::vector<std::string> out;
  for (const std::string& f : d.layers) out.push_back(f + " Layer");
  out.insert(out.end(), d.meshNodeSets.begin(), d.meshNodeSets.end());
  return out;
}

}  // namespace pf
