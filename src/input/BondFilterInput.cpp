// Peridigm's "Bond Filters" lists (in Discretization, and in an Initial Damage model) -> BondFilters.
// Its types (Peridigm_Discretization.cpp, createBondFilters): Rectangular_Plane, Disk, and Exodus Mesh, whose
// file's triangles and quads are the surfaces; the geometry is core/BondFilter.hpp.
#include <exodusII.h>

#include <algorithm>

#include "ExodusFile.hpp"
#include "Input.hpp"
#include "Sections.hpp"

namespace pf {

namespace {

using S = ParameterSpec;
const std::vector<std::string> kFilterTypes = {"Rectangular_Plane", "Disk", "Exodus Mesh"};

void addVector(std::vector<ParameterSpec>& s, const std::string& stem, const std::string& doc) {
  for (const char* a : {"_X", "_Y", "_Z"}) s.push_back(S::real(stem + a, std::string(a) == "_X" ? doc : "").need());
}

Vec3 vectorOf(const ParameterValues& v, const std::string& stem, bool nonZero, const std::string& file,
              const std::string& path) {
  const Vec3 r = {v.get(stem + "_X"), v.get(stem + "_Y"), v.get(stem + "_Z")};
  if (nonZero && r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0)
    fail(file, path, "'" + stem + "_X', '" + stem + "_Y', '" + stem + "_Z' are all zero: no direction");
  return r;
}

// The element blocks' polygons of a shell mesh, as Peridigm's GenesisToPolygons reads them: every element of a
// TRI or QUAD block, its nodes in connectivity order. firstThree: only the first three corners of each element
// (Peridigm's Initial Damage model makes a triangle of every element, a quad included).
void readPolygons(const std::string& mesh, bool firstThree, const std::string& file, const std::string& path,
                  std::vector<PolygonPatch>& out) {
  const ExodusFile f(mesh, file, path + "/File Name");
  const ExodusSummary& m = f.summary();
  std::vector<double> x(m.nodes), y(m.nodes), z(m.nodes, 0.0);
  if (m.nodes > 0)
    f.check(ex_get_coord(f.id(), x.data(), y.data(), m.dimension > 2 ? z.data() : nullptr), "ex_get_coord");
  const std::vector<std::string> types = {"TRI", "TRI3", "TRIANGLE", "QUAD", "QUAD4", "SHELL", "SHELL3", "SHELL4"};
  for (const ExodusBlock& b : m.blocks) {
    if (b.elements == 0) continue;
    if (std::find(types.begin(), types.end(), b.type) == types.end() || b.nodesPerElement < 3 || b.nodesPerElement > 4)
      f.fail("block " + std::to_string(b.id) + " has " + b.type + " elements with " + std::to_string(b.nodesPerElement) +
             " nodes; a bond filter mesh holds triangles and quads (TRI, TRI3, QUAD, QUAD4, SHELL3, SHELL4)");
    std::vector<int> conn(b.elements * b.nodesPerElement);
    f.check(ex_get_conn(f.id(), EX_ELEM_BLOCK, b.id, conn.data(), nullptr, nullptr), "ex_get_conn");
    for (long long e = 0; e < b.elements; ++e) {
      std::vector<Vec3> corners;
      for (long long k = 0; k < (firstThree ? 3 : b.nodesPerElement); ++k) {
        const int n = conn[e * b.nodesPerElement + k] - 1;
        if (n < 0 || n >= m.nodes) f.fail("element " + std::to_string(b.first + e + 1) + " names a node out of range");
        corners.push_back({x[n], y[n], z[n]});
      }
      PolygonPatch p;
      if (!makePolygon(corners, p))
        f.fail("element " + std::to_string(b.first + e + 1) + " has zero area: no surface to cut bonds with");
      out.push_back(p);
    }
  }
}

}  // namespace

std::vector<ParameterSpec> bondFilterSpecs(const std::string& type) {
  std::vector<ParameterSpec> s = {S::text("Type", "the surface (sections below)").need().oneOf(kFilterTypes)};
  if (type == "Rectangular_Plane") {
    addVector(s, "Normal", "normal of the plane (`_X`, `_Y`, `_Z`), not all zero; used as given, not normalised");
    addVector(s, "Lower_Left_Corner", "a corner of the rectangle, in the plane");
    addVector(s, "Bottom_Unit_Vector", "direction of the bottom edge from the corner, not all zero; used as given "
                                       "(Peridigm does not normalise it); the side edge runs along bottom × normal");
    s.push_back(S::real("Bottom_Length", "length of the bottom edge").need().positive());
    s.push_back(S::real("Side_Length", "length of the side edge").need().positive());
  }
  if (type == "Disk") {
    addVector(s, "Center", "centre of the disk");
    addVector(s, "Normal", "normal of the disk's plane, not all zero");
    s.push_back(S::real("Radius", "radius; the rim itself cuts nothing (Peridigm's strict test)").need().positive());
  }
  if (type == "Exodus Mesh")
    s.push_back(S::text("File Name", "Exodus II file of triangles and quads (TRI, TRI3, QUAD, QUAD4, SHELL3, SHELL4 "
                                     "blocks): every element is a surface; relative to the deck's directory").need());
  return s;
}

BondFilters parseBondFilters(const PL& list, const std::string& file, const std::string& path, const std::string& dir,
                             bool initialDamage) {
  BondFilters out;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it), fpath = path + "/" + name;
    if (!list.entry(it).isList()) fail(file, path, "unknown parameter '" + name + "' (each bond filter is a sub-list)");
    const PL& f = list.sublist(name);
    if (!f.isParameter("Type")) fail(file, fpath, "missing required parameter 'Type'");
    const std::string type = getText(f, "Type", "");
    if (std::find(kFilterTypes.begin(), kFilterTypes.end(), type) == kFilterTypes.end())
      fail(file, fpath, "'Type' = '" + type + "' is not a bond filter type (" + joinNames(kFilterTypes) + ")");
    const ParameterValues v = readList(f, bondFilterSpecs(type), {}, file, fpath);
    if (type == "Rectangular_Plane") {
      PlanePatch p;
      p.normal = vectorOf(v, "Normal", true, file, fpath);
      p.corner = vectorOf(v, "Lower_Left_Corner", false, file, fpath);
      p.bottom = vectorOf(v, "Bottom_Unit_Vector", true, file, fpath);
      const Vec3& n = p.normal;
      const Vec3& u = p.bottom;
      if (u[1] * n[2] - u[2] * n[1] == 0.0 && u[2] * n[0] - u[0] * n[2] == 0.0 && u[0] * n[1] - u[1] * n[0] == 0.0)
        fail(file, fpath, "'Bottom_Unit_Vector' is parallel to 'Normal': the rectangle has no side direction");
      p.bottomLength = v.get("Bottom_Length");
      p.sideLength = v.get("Side_Length");
      out.planes.push_back(p);
    } else if (type == "Disk") {
      out.disks.push_back({vectorOf(v, "Center", false, file, fpath), vectorOf(v, "Normal", true, file, fpath),
                           v.get("Radius")});
    } else {
      readPolygons(resolvePath(v.text("File Name"), dir), initialDamage, file, fpath, out.polygons);
    }
  }
  return out;
}

}  // namespace pf
