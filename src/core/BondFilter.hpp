#pragma once
// Peridigm's bond filters (its src/io/pdneigh/BondFilter.cxx): surfaces no bond may cross. A bond p0 -> p1 (p0
// the point whose family is built) is cut when the segment meets the surface: the line meets the surface's
// plane at a parameter t in [0, 1] (both ends included, so a point lying on the plane loses every bond that
// is not parallel to it) and the meeting point lies in the surface's outline, as Peridigm decides it:
//  - Rectangular_Plane: edges closed (a meeting point on an edge, to 1e-15, cuts), corner rule below;
//  - Disk: rim open (|x - c|^2 < r^2 strictly);
//  - triangles and quads of an Exodus Mesh: edges closed (barycentric coordinates > -1e-14).
// A bond parallel to the plane (|(p1 - p0).n| below 1e-14, 1e-15 for a disk: Peridigm's absolute
// tolerances) is never cut, even lying in the plane.
// Used by the discretization ("Discretization/Bond Filters": cut bonds are not made) and by the Initial
// Damage model (cut bonds start broken).
#include <array>
#include <vector>

namespace pf {

using Vec3 = std::array<double, 3>;

// "Rectangular_Plane": the plane through corner with the given normal n; the rectangle spans bottomLength
// along `bottom` from the corner and sideLength along bottom x n. Neither vector is normalised (Peridigm
// uses them as given: its PrecrackedPlateTwoCracks deck gives a bottom vector (1, 4, 0) with normal (0, 1, 0)).
struct PlanePatch {
  Vec3 normal{}, corner{}, bottom{};
  double bottomLength = 0.0, sideLength = 0.0;
};

// "Disk": the disk of the given radius about centre in the plane with the given normal.
struct DiskPatch {
  Vec3 centre{}, normal{};
  double radius = 0.0;
};

// One element of an "Exodus Mesh" filter: a triangle (corners 3) or a quad (corners 4, split along v0-v2).
struct PolygonPatch {
  std::array<Vec3, 4> v{};
  int corners = 3;
  Vec3 normal{};  // unit: (v1 - v0) x (v[corners-1] - v0) normalised
};

// A triangle or quad from its corners; false (nothing made) for a polygon of zero area.
bool makePolygon(const std::vector<Vec3>& corners, PolygonPatch& out);

bool cuts(const PlanePatch& s, const double* p0, const double* p1);
bool cuts(const DiskPatch& s, const double* p0, const double* p1);
bool cuts(const PolygonPatch& s, const double* p0, const double* p1);

// The filters of one list, every kind; a bond is cut if any of them cuts it.
struct BondFilters {
  std::vector<PlanePatch> planes;
  std::vector<DiskPatch> disks;
  std::vector<PolygonPatch> polygons;
  bool empty() const { return planes.empty() && disks.empty() && polygons.empty(); }
};

}  // namespace pf
