// Boundary Conditions of Type "Rigid Wall" -> RigidWallSpecs: a plane (a point and its normal) that the
// points of a node set may not cross. Only Verlet enforces it, so a deck with another solver is refused
// rather than run without its wall.
#include <cmath>

#include "Sections.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

// The normal as given, scaled to unit length: any non-zero vector names a direction, so it need not be
// normalised by hand (a zero one names none and is refused).
std::array<double, 3> unitNormal(const ParameterValues& v, const std::string& file, const std::string& path) {
  std::array<double, 3> n = {v.get("Normal X"), v.get("Normal Y"), v.get("Normal Z")};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0.0) || !std::isfinite(len))
    fail(file, path, "'Normal X', 'Normal Y', 'Normal Z' must give a finite, non-zero direction");
  for (double& c : n) c /= len;
  return n;
}

}  // namespace

std::vector<ParameterSpec> rigidWallSpecs() {
  std::vector<ParameterSpec> s = {S::text("Type", "`Rigid Wall`").need(),
                                  S::text("Node Set", "the points the wall stops (`All`: every point)").byDefault("All")};
  for (const char* a : {"X", "Y", "Z"}) s.push_back(S::real(std::string("Point ") + a, "a point of the plane").byDefault("0"));
  for (const char* a : {"X", "Y", "Z"})
    s.push_back(S::real(std::string("Normal ") + a, "normal of the plane, pointing to the side the body stays on "
                                                    "(scaled to unit length)").byDefault("0"));
  return s;
}

std::vector<RigidWallSpec> parseRigidWalls(const PL& bcs, const std::set<std::string>& nodeSets,
                                           const std::vector<SolverSpec>& solvers, const std::string& file) {
  std::vector<RigidWallSpec> out;
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    if (!bcs.entry(it).isList()) continue;
    const PL& b = bcs.sublist(bcs.name(it));
    if (!b.isParameter("Type") || !b.getEntry("Type").isType<std::string>() ||
        b.get<std::string>("Type") != "Rigid Wall")
      continue;
    const std::string path = "Boundary Conditions/" + bcs.name(it);
    const ParameterValues v = readList(b, rigidWallSpecs(), {}, file, path);
    RigidWallSpec w;
    w.name = bcs.name(it);
    w.nodeSet = v.text("Node Set");
    if (!nodeSets.count(w.nodeSet)) fail(file, path, "'Node Set' = '" + w.nodeSet + "' is not defined in Boundary Conditions");
    w.point = {v.get("Point X"), v.get("Point Y"), v.get("Point Z")};
    w.normal = unitNormal(v, file, path);
    for (const SolverSpec& s : solvers)
      if (s.type != "Verlet")
        fail(file, path, "a Rigid Wall is enforced by the Verlet solver only; '" + s.listName + "' is '" + s.type + "'");
    out.push_back(w);
  }
  return out;
}

}  // namespace pf
