#include "BondFilter.hpp"

#include <cmath>

namespace pf {

namespace {

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The parameter t where the line p0 + t (p1 - p0) meets the plane through r0 with normal n, and that point x;
// false when the segment misses the plane (t outside [0, 1]) or is parallel to it (|(p1 - p0).n| < tol).
// Peridigm's FinitePlane::bondIntersectInfinitePlane and its Disk/Triangle/Quad copies.
bool meetsPlane(const double* r0, const double* n, const double* p0, const double* p1, double tol, double* x) {
  const double num = (r0[0] - p0[0]) * n[0] + (r0[1] - p0[1]) * n[1] + (r0[2] - p0[2]) * n[2];
  const double den = (p1[0] - p0[0]) * n[0] + (p1[1] - p0[1]) * n[1] + (p1[2] - p0[2]) * n[2];
  if (std::fabs(den) < tol) return false;
  const double t = num / den;
  if (!(t >= 0.0 && t <= 1.0)) return false;
  for (int d = 0; d < 3; ++d) x[d] = p0[d] + t * (p1[d] - p0[d]);
  return true;
}

// Whether x lies in the triangle o, o + a, o + b (barycentric coordinates along a and b, each > -tol, their sum
// < 1 + 2 tol: Peridigm's TriangleFilter::pointInTriangle, a = v2 - v0, b = v1 - v0 there).
bool inTriangle(const double* o, const double* a, const double* b, const double* x, double tol) {
  const double c[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
  const double aa = dot(a, a), ab = dot(a, b), ac = dot(a, c), bb = dot(b, b), bc = dot(b, c);
  const double det = aa * bb - ab * ab;
  const double alpha = (bb * ac - ab * bc) / det, beta = (aa * bc - ab * ac) / det;
  return alpha > -tol && beta > -tol && alpha + beta < 1.0 + 2.0 * tol;
}

}  // namespace

bool makePolygon(const std::vector<Vec3>& corners, PolygonPatch& out) {
  if (corners.size() != 3 && corners.size() != 4) return false;
  out.corners = static_cast<int>(corners.size());
  for (int k = 0; k < out.corners; ++k) out.v[k] = corners[k];
  const Vec3& o = out.v[0];
  const Vec3& l = out.v[out.corners - 1];
  const double a[3] = {out.v[1][0] - o[0], out.v[1][1] - o[1], out.v[1][2] - o[2]};
  const double b[3] = {l[0] - o[0], l[1] - o[1], l[2] - o[2]};
  Vec3 n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0.0) || !std::isfinite(len)) return false;
  for (double& c : n) c /= len;
  out.normal = n;
  return true;
}

bool cuts(const PlanePatch& s, const double* p0, const double* p1) {
  double x[3];
  if (!meetsPlane(s.corner.data(), s.normal.data(), p0, p1, 1e-14, x)) return false;
  // Peridigm's FinitePlane::bondIntersect: the side direction is bottom x normal; the point's coordinates
  // along bottom and side from the corner, over each edge's length, lie in (-1e-15, 1 + 1e-15) (the lower
  // bound on the coordinate itself, as Peridigm writes it).
  const double* u = s.bottom.data();
  const double* n = s.normal.data();
  const double side[3] = {-u[2] * n[1] + u[1] * n[2], u[2] * n[0] - u[0] * n[2], -u[1] * n[0] + u[0] * n[1]};
  const double dr[3] = {x[0] - s.corner[0], x[1] - s.corner[1], x[2] - s.corner[2]};
  const double zero = 1e-15, one = 1.0 + zero;
  const double along = dot(dr, side), across = dot(dr, u);
  return -zero < along && along / s.sideLength < one && -zero < across && across / s.bottomLength < one;
}

bool cuts(const DiskPatch& s, const double* p0, const double* p1) {
  double x[3];
  if (!meetsPlane(s.centre.data(), s.normal.data(), p0, p1, 1e-15, x)) return false;
  const double d[3] = {x[0] - s.centre[0], x[1] - s.centre[1], x[2] - s.centre[2]};
  return dot(d, d) < s.radius * s.radius;
}

bool cuts(const PolygonPatch& s, const double* p0, const double* p1) {
  double x[3];
  const double tol = 1e-14;
  if (!meetsPlane(s.v[0].data(), s.normal.data(), p0, p1, tol, x)) return false;
  const double* o = s.v[0].data();
  const double a[3] = {s.v[2][0] - o[0], s.v[2][1] - o[1], s.v[2][2] - o[2]};
  const double b[3] = {s.v[1][0] - o[0], s.v[1][1] - o[1], s.v[1][2] - o[2]};
  if (inTriangle(o, a, b, x, tol)) return true;
  if (s.corners == 3) return false;
  const double d[3] = {s.v[3][0] - o[0], s.v[3][1] - o[1], s.v[3][2] - o[2]};
  return inTriangle(o, a, d, x, tol);  // Peridigm's QuadFilter: the second half v0, v2, v3
}

}  // namespace pf
