// Element centroids and measures of the Exodus discretization (src/discretization/ElementGeometry.hpp) against
// closed forms: boxes, parallelepipeds, tetrahedra, wedges, pyramids, a frustum (planar faces: the tetrahedral
// split is exact), 2D quads and triangles, inverted elements, and the Exodus type names. A hexahedron with
// non-planar faces is checked against the trilinear map integrated by 2x2x2 Gauss quadrature (exact for its
// volume) and against the centroid of the polyhedron the split describes, computed here another way.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "discretization/ElementGeometry.hpp"

namespace {

using pf::ElementGeometry;
using pf::ElementShape;
using Vec = std::array<double, 3>;

// The unit cube's corners in Exodus HEX8 order: bottom face 0-1-2-3 counter-clockwise seen from +z, then top.
const double kUnitCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

std::vector<double> flat(const std::vector<Vec>& nodes) {
  std::vector<double> x;
  for (const Vec& p : nodes) x.insert(x.end(), p.begin(), p.end());
  return x;
}

std::vector<Vec> unitCube() {
  std::vector<Vec> n;
  for (const auto& p : kUnitCube) n.push_back({p[0], p[1], p[2]});
  return n;
}

ElementGeometry geometry(ElementShape shape, const std::vector<Vec>& nodes) {
  const std::vector<double> x = flat(nodes);
  return pf::elementGeometry(shape, x.data());
}

void expectCentroid(const ElementGeometry& g, const Vec& want, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(g.centroid[i], want[i], tol) << "centroid component " << i;
}

double det3(const double a[3][3]) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// Signed volume of the tetrahedron (o, a, b, c).
double tetVolume(const Vec& o, const Vec& a, const Vec& b, const Vec& c) {
  const double m[3][3] = {{a[0] - o[0], a[1] - o[1], a[2] - o[2]},
                          {b[0] - o[0], b[1] - o[1], b[2] - o[2]},
                          {c[0] - o[0], c[1] - o[1], c[2] - o[2]}};
  return det3(m) / 6.0;
}

// Volume and centroid of the trilinear hexahedron x(r, s, t) = sum_a N_a x_a by n x n x n Gauss-Legendre
// quadrature on [0, 1]^3 (n = 2 is exact for the volume: det J has degree <= 2 in each of r, s, t).
struct Moments {
  double volume = 0.0;
  Vec centroid{};
};
Moments trilinear(const std::vector<Vec>& x, int n) {
  const double g2[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)}, w2[2] = {0.5, 0.5};
  const double g3[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)},
               w3[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  const double* g = n == 2 ? g2 : g3;
  const double* w = n == 2 ? w2 : w3;
  Moments m;
  Vec moment{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double q[3] = {g[i], g[j], g[k]};
        double jac[3][3] = {};  // jac[d][e] = d x_d / d q_e
        Vec at{};
        for (int a = 0; a < 8; ++a) {
          double f[3], df[3];  // the 1D shape factors of node a and their derivatives
          for (int e = 0; e < 3; ++e) {
            const bool one = kUnitCube[a][e] > 0.5;
            f[e] = one ? q[e] : 1.0 - q[e];
            df[e] = one ? 1.0 : -1.0;
          }
          const double N = f[0] * f[1] * f[2];
          const double dN[3] = {df[0] * f[1] * f[2], f[0] * df[1] * f[2], f[0] * f[1] * df[2]};
          for (int d = 0; d < 3; ++d) {
            at[d] += N * x[a][d];
            for (int e = 0; e < 3; ++e) jac[d][e] += dN[e] * x[a][d];
          }
        }
        const double dv = w[i] * w[j] * w[k] * det3(jac);
        m.volume += dv;
        for (int d = 0; d < 3; ++d) moment[d] += dv * at[d];
      }
  for (int d = 0; d < 3; ++d) m.centroid[d] = moment[d] / m.volume;
  return m;
}

// The polyhedron of the hexahedron's faces, each quadrilateral fanned into four triangles from its corners'
// mean (the surface the 24-tetrahedron split encloses): volume and centroid from the divergence theorem, as
// tetrahedra on the origin (not on the element's centre, as the code under test does).
Moments fannedSurface(const std::vector<Vec>& x) {
  // Faces counter-clockwise seen from outside (Exodus side sets 1..6).
  const int faces[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  const Vec o{0.0, 0.0, 0.0};
  Moments m;
  Vec moment{};
  for (const auto& f : faces) {
    Vec c{};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) c[d] += 0.25 * x[f[k]][d];
    for (int k = 0; k < 4; ++k) {
      const Vec& a = x[f[k]];
      const Vec& b = x[f[(k + 1) % 4]];
      const double v = tetVolume(o, a, b, c);
      m.volume += v;
      for (int d = 0; d < 3; ++d) moment[d] += v * (o[d] + a[d] + b[d] + c[d]) / 4.0;
    }
  }
  for (int d = 0; d < 3; ++d) m.centroid[d] = moment[d] / m.volume;
  return m;
}

TEST(ElementGeometry, UnitCubeHex) {
  const ElementGeometry g = geometry(ElementShape::Hex, unitCube());
  EXPECT_NEAR(g.measure, 1.0, 1e-15);
  expectCentroid(g, {0.5, 0.5, 0.5}, 1e-15);
}

TEST(ElementGeometry, BoxHexAwayFromTheOrigin) {
  // [2, 2.5] x [-1, 2] x [10, 10.25]: volume 0.375, centroid the box's centre.
  std::vector<Vec> n;
  for (const auto& p : kUnitCube) n.push_back({2.0 + 0.5 * p[0], -1.0 + 3.0 * p[1], 10.0 + 0.25 * p[2]});
  const ElementGeometry g = geometry(ElementShape::Hex, n);
  EXPECT_NEAR(g.measure, 0.375, 1e-14);
  expectCentroid(g, {2.25, 0.5, 10.125}, 1e-14);
}

TEST(ElementGeometry, ParallelepipedHex) {
  // x = o + A q, q the unit cube: volume det A, centroid o + A (1/2, 1/2, 1/2).
  const double A[3][3] = {{2.0, 0.5, -0.3}, {0.2, 1.5, 0.4}, {-0.1, 0.3, 0.8}};
  const Vec o{1.0, -2.0, 0.5};
  std::vector<Vec> n;
  for (const auto& q : kUnitCube) {
    Vec p = o;
    for (int d = 0; d < 3; ++d)
      for (int e = 0; e < 3; ++e) p[d] += A[d][e] * q[e];
    n.push_back(p);
  }
  const double det = det3(A);
  ASSERT_GT(det, 0.0);
  const ElementGeometry g = geometry(ElementShape::Hex, n);
  EXPECT_NEAR(g.measure, det, 1e-14 * det);
  Vec c = o;
  for (int d = 0; d < 3; ++d)
    for (int e = 0; e < 3; ++e) c[d] += 0.5 * A[d][e];
  expectCentroid(g, c, 1e-14);
}

TEST(ElementGeometry, FrustumHexWithPlanarFaces) {
  // A square frustum: base [0, 2]^2 at z = 0, top [0.5, 1.5]^2 at z = 1; every face is planar, so the
  // tetrahedra tile it exactly. V = h (A1 + A2 + sqrt(A1 A2)) / 3 = 7/3; the centroid's height
  // h (A1 + 2 sqrt(A1 A2) + 3 A2) / (4 (A1 + sqrt(A1 A2) + A2)) = 11/28.
  const std::vector<Vec> n = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                              {0.5, 0.5, 1}, {1.5, 0.5, 1}, {1.5, 1.5, 1}, {0.5, 1.5, 1}};
  const ElementGeometry g = geometry(ElementShape::Hex, n);
  EXPECT_NEAR(g.measure, 7.0 / 3.0, 1e-14);
  expectCentroid(g, {1.0, 1.0, 11.0 / 28.0}, 1e-14);
  // The trilinear map of these corners is the frustum itself: the quadrature agrees.
  const Moments t = trilinear(n, 3);
  EXPECT_NEAR(t.volume, 7.0 / 3.0, 1e-14);
  EXPECT_NEAR(t.centroid[2], 11.0 / 28.0, 1e-14);
}

TEST(ElementGeometry, HexWithNonPlanarFaces) {
  // The unit cube with three corners moved: three faces become twisted (non-planar).
  std::vector<Vec> n = unitCube();
  n[6] = {1.3, 1.2, 1.4};
  n[1] = {0.9, -0.1, 0.2};
  n[4] = {0.1, 0.05, 0.8};
  const ElementGeometry g = geometry(ElementShape::Hex, n);
  // Volume: the 24-tetrahedron split (faces fanned from their corners' mean) reproduces the trilinear hex's
  // volume exactly (measured: equal to round-off, 1.0654166666666667 both, here and on random hexahedra), so
  // the bound is round-off.
  const Moments t = trilinear(n, 2);
  EXPECT_NEAR(t.volume, 1.0654166666666667, 1e-14);  // the quadrature itself, as measured with numpy
  EXPECT_NEAR(g.measure, t.volume, 1e-13 * t.volume);
  // Centroid: that of the fanned polyhedron (computed here from the origin), to round-off ...
  const Moments s = fannedSurface(n);
  EXPECT_NEAR(s.volume, g.measure, 1e-13 * g.measure);
  expectCentroid(g, s.centroid, 1e-13);
  // ... which is not the trilinear hex's centroid: measured differences 1.8e-4, 1.2e-4, 2.2e-4 (the two
  // shapes differ inside the twisted faces). Bound 1e-3: the order measured, far below the element size.
  const Moments t3 = trilinear(n, 3);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(t3.centroid[d], t.centroid[d], 1e-14) << "quadrature order";
    EXPECT_NEAR(g.centroid[d], t.centroid[d], 1e-3) << "component " << d;
  }
}

TEST(ElementGeometry, InvertedHexIsNegative) {
  // Nodes 0-3 swapped with 4-7: the element is the cube turned inside out.
  const std::vector<Vec> c = unitCube();
  std::vector<Vec> n(c.begin() + 4, c.end());
  n.insert(n.end(), c.begin(), c.begin() + 4);
  const ElementGeometry g = geometry(ElementShape::Hex, n);
  EXPECT_NEAR(g.measure, -1.0, 1e-15);
  EXPECT_LT(g.measure, 0.0);
}

TEST(ElementGeometry, Tetrahedron) {
  const ElementGeometry unit = geometry(ElementShape::Tet, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_NEAR(unit.measure, 1.0 / 6.0, 1e-16);
  expectCentroid(unit, {0.25, 0.25, 0.25}, 1e-16);
  // A general one: volume |det(b - a, c - a, d - a)| / 6, centroid the vertices' mean.
  const std::vector<Vec> n = {{1.0, 2.0, -1.0}, {3.5, 2.2, -0.8}, {1.4, 4.0, -0.5}, {1.2, 2.5, 2.0}};
  const double m[3][3] = {{2.5, 0.2, 0.2}, {0.4, 2.0, 0.5}, {0.2, 0.5, 3.0}};
  const ElementGeometry g = geometry(ElementShape::Tet, n);
  EXPECT_NEAR(g.measure, det3(m) / 6.0, 1e-14);
  expectCentroid(g, {(1.0 + 3.5 + 1.4 + 1.2) / 4, (2.0 + 2.2 + 4.0 + 2.5) / 4, (-1.0 - 0.8 - 0.5 + 2.0) / 4}, 1e-14);
  // Two nodes swapped: negative.
  EXPECT_LT(geometry(ElementShape::Tet, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}).measure, 0.0);
}

TEST(ElementGeometry, Wedge) {
  // Triangle (0,0), (2,0), (0,1) (area 1) from z = 1 to z = 4: volume 3, centroid (2/3, 1/3, 2.5).
  const std::vector<Vec> n = {{0, 0, 1}, {2, 0, 1}, {0, 1, 1}, {0, 0, 4}, {2, 0, 4}, {0, 1, 4}};
  const ElementGeometry g = geometry(ElementShape::Wedge, n);
  EXPECT_NEAR(g.measure, 3.0, 1e-14);
  expectCentroid(g, {2.0 / 3.0, 1.0 / 3.0, 2.5}, 1e-14);
  // A sheared prism (top translated by (0.5, 0.25)): same volume, centroid moved by half the shift.
  std::vector<Vec> s = n;
  for (int k = 3; k < 6; ++k) s[k][0] += 0.5, s[k][1] += 0.25;
  const ElementGeometry h = geometry(ElementShape::Wedge, s);
  EXPECT_NEAR(h.measure, 3.0, 1e-14);
  expectCentroid(h, {2.0 / 3.0 + 0.25, 1.0 / 3.0 + 0.125, 2.5}, 1e-14);
}

TEST(ElementGeometry, Pyramid) {
  // Base [0, 2]^2 at z = 0, apex (1, 1, 3): volume 4 * 3 / 3 = 4, centroid at a quarter of the height.
  const std::vector<Vec> n = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 3}};
  const ElementGeometry g = geometry(ElementShape::Pyramid, n);
  EXPECT_NEAR(g.measure, 4.0, 1e-14);
  expectCentroid(g, {1.0, 1.0, 0.75}, 1e-14);
  // An oblique one (apex over (1.6, 0.4)): same volume; centroid = base centre + (apex - base centre) / 4.
  std::vector<Vec> o = n;
  o[4] = {1.6, 0.4, 3.0};
  const ElementGeometry h = geometry(ElementShape::Pyramid, o);
  EXPECT_NEAR(h.measure, 4.0, 1e-14);
  expectCentroid(h, {1.0 + 0.6 / 4, 1.0 - 0.6 / 4, 0.75}, 1e-14);
}

TEST(ElementGeometry, QuadAndTriangleInThePlane) {
  const ElementGeometry rect = geometry(ElementShape::Quad, {{1, 2, 0}, {3, 2, 0}, {3, 3, 0}, {1, 3, 0}});
  EXPECT_NEAR(rect.measure, 2.0, 1e-15);
  expectCentroid(rect, {2.0, 2.5, 0.0}, 1e-15);
  // Trapezoid, bases 4 (y = 0) and 2 (y = 2): area 6, centroid height h (b1 + 2 b2) / (3 (b1 + b2)) = 8/9.
  const ElementGeometry trap = geometry(ElementShape::Quad, {{0, 0, 0}, {4, 0, 0}, {3, 2, 0}, {1, 2, 0}});
  EXPECT_NEAR(trap.measure, 6.0, 1e-14);
  expectCentroid(trap, {2.0, 8.0 / 9.0, 0.0}, 1e-14);
  const ElementGeometry tri = geometry(ElementShape::Tri, {{0, 0, 0}, {3, 0, 0}, {0, 2, 0}});
  EXPECT_NEAR(tri.measure, 3.0, 1e-15);
  expectCentroid(tri, {1.0, 2.0 / 3.0, 0.0}, 1e-15);
  // Clockwise: negative.
  EXPECT_LT(geometry(ElementShape::Quad, {{1, 2, 0}, {1, 3, 0}, {3, 3, 0}, {3, 2, 0}}).measure, 0.0);
  EXPECT_LT(geometry(ElementShape::Tri, {{0, 0, 0}, {0, 2, 0}, {3, 0, 0}}).measure, 0.0);
}

TEST(ElementGeometry, ShapeNames) {
  EXPECT_EQ(pf::elementShape("HEX8"), ElementShape::Hex);
  EXPECT_EQ(pf::elementShape("hex"), ElementShape::Hex);
  EXPECT_EQ(pf::elementShape("HEX20"), ElementShape::Hex);
  EXPECT_EQ(pf::elementShape("TETRA"), ElementShape::Tet);
  EXPECT_EQ(pf::elementShape("TET10"), ElementShape::Tet);
  EXPECT_EQ(pf::elementShape("tetra4"), ElementShape::Tet);
  EXPECT_EQ(pf::elementShape("SPHERE"), ElementShape::Sphere);
  EXPECT_EQ(pf::elementShape("QUAD4"), ElementShape::Quad);
  EXPECT_EQ(pf::elementShape("TRI3"), ElementShape::Tri);
  EXPECT_EQ(pf::elementShape("WEDGE6"), ElementShape::Wedge);
  EXPECT_EQ(pf::elementShape("PYRAMID5"), ElementShape::Pyramid);
  EXPECT_EQ(pf::elementShape("FOO"), ElementShape::Unknown);
  EXPECT_EQ(pf::elementShape(""), ElementShape::Unknown);

  EXPECT_EQ(pf::cornerNodes(ElementShape::Sphere), 1);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Tet), 4);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Hex), 8);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Wedge), 6);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Pyramid), 5);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Quad), 4);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Tri), 3);
  EXPECT_EQ(pf::cornerNodes(ElementShape::Unknown), 0);
  EXPECT_TRUE(pf::isPlanarShape(ElementShape::Quad));
  EXPECT_TRUE(pf::isPlanarShape(ElementShape::Tri));
  EXPECT_FALSE(pf::isPlanarShape(ElementShape::Hex));
  EXPECT_FALSE(pf::isPlanarShape(ElementShape::Sphere));

  const double point[3] = {0.0, 0.0, 0.0};
  EXPECT_THROW(pf::elementGeometry(ElementShape::Sphere, point), std::logic_error);
  EXPECT_THROW(pf::elementGeometry(ElementShape::Unknown, point), std::logic_error);
}

}  // namespace
