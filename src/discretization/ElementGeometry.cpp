#include "ElementGeometry.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <vector>

namespace pf {

namespace {

using Vec = std::array<double, 3>;

// Signed volume a . (b x c) / 6 of the tetrahedron (p0, p1, p2, p3), a = p1 - p0, b = p2 - p0, c = p3 - p0.
double tetVolume(const Vec& p0, const Vec& p1, const Vec& p2, const Vec& p3) {
  Vec a, b, c;
  for (int i = 0; i < 3; ++i) a[i] = p1[i] - p0[i], b[i] = p2[i] - p0[i], c[i] = p3[i] - p0[i];
  return (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6.0;
}

// A face: its corner loop, counter-clockwise seen from outside (Exodus' side numbering). Each edge (l_k, l_k+1)
// with the face's barycentre f and the element centre c makes the tetrahedron (l_k+1, l_k, f, c), positive for
// a valid element; a triangle makes the one tetrahedron (l_1, l_0, l_2, c).
struct Face {
  std::vector<int> loop;
};

// Peridigm's hexahedron (Peridigm_GeometryUtils): faces by their barycentre nodes, then the 24 tetrahedra's first
// two nodes in Peridigm's order, so that the sums round as Peridigm's do.
const int kHexFaceNodes[6][4] = {{0, 1, 4, 5}, {1, 2, 5, 6}, {2, 3, 6, 7}, {0, 3, 4, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
const int kHexTets[6][4][2] = {{{1, 0}, {5, 1}, {4, 5}, {0, 4}}, {{2, 1}, {6, 2}, {5, 6}, {1, 5}},
                               {{3, 2}, {7, 3}, {6, 7}, {2, 6}}, {{0, 3}, {3, 7}, {7, 4}, {4, 0}},
                               {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {{5, 4}, {4, 7}, {7, 6}, {6, 5}}};

const std::vector<Face> kWedgeFaces = {{{0, 1, 4, 3}}, {{1, 2, 5, 4}}, {{0, 3, 5, 2}}, {{0, 2, 1}}, {{3, 4, 5}}};
const std::vector<Face> kPyramidFaces = {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}, {{0, 3, 2, 1}}};

Vec node(const double* x, int i) { return {x[3 * i], x[3 * i + 1], x[3 * i + 2]}; }

struct Accumulator {
  double volume = 0.0;
  Vec moment{};
  void add(const Vec& p0, const Vec& p1, const Vec& p2, const Vec& p3) {
    const double v = tetVolume(p0, p1, p2, p3);
    volume += v;
    for (int i = 0; i < 3; ++i) moment[i] += (p0[i] + p1[i] + p2[i] + p3[i]) * 0.25 * v;
  }
  ElementGeometry result() const {
    ElementGeometry g;
    g.measure = volume;
    for (int i = 0; i < 3; ++i) g.centroid[i] = volume != 0.0 ? moment[i] / volume : 0.0;
    return g;
  }
};

ElementGeometry hex(const double* x) {
  Vec f[6], c;
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i)
      f[k][i] = 0.25 * (x[3 * kHexFaceNodes[k][0] + i] + x[3 * kHexFaceNodes[k][1] + i] + x[3 * kHexFaceNodes[k][2] + i] +
                        x[3 * kHexFaceNodes[k][3] + i]);
  for (int i = 0; i < 3; ++i) c[i] = 0.5 * (f[4][i] + f[5][i]);
  Accumulator a;
  for (int k = 0; k < 6; ++k)
    for (int t = 0; t < 4; ++t) a.add(node(x, kHexTets[k][t][0]), node(x, kHexTets[k][t][1]), f[k], c);
  return a.result();
}

ElementGeometry fanned(const double* x, int corners, const std::vector<Face>& faces) {
  Vec c{};
  for (int n = 0; n < corners; ++n)
    for (int i = 0; i < 3; ++i) c[i] += x[3 * n + i] / corners;
  Accumulator a;
  for (const Face& face : faces) {
    const std::vector<int>& l = face.loop;
    if (l.size() == 3) {
      a.add(node(x, l[1]), node(x, l[0]), node(x, l[2]), c);
      continue;
    }
    Vec f{};
    for (int n : l)
      for (int i = 0; i < 3; ++i) f[i] += x[3 * n + i] / static_cast<double>(l.size());
    for (std::size_t k = 0; k < l.size(); ++k) a.add(node(x, l[(k + 1) % l.size()]), node(x, l[k]), f, c);
  }
  return a.result();
}

ElementGeometry tet(const double* x) {
  Accumulator a;
  a.add(node(x, 0), node(x, 1), node(x, 2), node(x, 3));
  return a.result();
}

// 2D: the polygon's triangles (l_k, l_k+1, c) in the xy-plane, c the corners' mean; counter-clockwise is positive.
ElementGeometry polygon(const double* x, int corners) {
  double cx = 0.0, cy = 0.0;
  for (int n = 0; n < corners; ++n) cx += x[3 * n] / corners, cy += x[3 * n + 1] / corners;
  ElementGeometry g;
  double mx = 0.0, my = 0.0;
  for (int k = 0; k < corners; ++k) {
    const double* p = x + 3 * k;
    const double* q = x + 3 * ((k + 1) % corners);
    const double area = 0.5 * ((p[0] - cx) * (q[1] - cy) - (q[0] - cx) * (p[1] - cy));
    g.measure += area;
    mx += area * (p[0] + q[0] + cx) / 3.0;
    my += area * (p[1] + q[1] + cy) / 3.0;
  }
  if (g.measure != 0.0) g.centroid = {mx / g.measure, my / g.measure, 0.0};
  return g;
}

}  // namespace

ElementShape elementShape(const std::string& exodusType) {
  std::string t = exodusType;
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char ch) { return std::toupper(ch); });
  auto is = [&](std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (t == n) return true;
    return false;
  };
  if (is({"SPHERE", "SPHERE1"})) return ElementShape::Sphere;
  if (is({"TET", "TETRA", "TET4", "TETRA4", "TET10", "TETRA10"})) return ElementShape::Tet;
  if (is({"HEX", "HEX8", "HEX20", "HEX27"})) return ElementShape::Hex;
  if (is({"WEDGE", "WEDGE6", "WEDGE15"})) return ElementShape::Wedge;
  if (is({"PYRAMID", "PYRAMID5", "PYRAMID13"})) return ElementShape::Pyramid;
  if (is({"QUAD", "QUAD4", "QUAD8", "QUAD9"})) return ElementShape::Quad;
  if (is({"TRI", "TRI3", "TRI6", "TRIANGLE"})) return ElementShape::Tri;
  return ElementShape::Unknown;
}

int cornerNodes(ElementShape shape) {
  switch (shape) {
    case ElementShape::Sphere: return 1;
    case ElementShape::Tet: return 4;
    case ElementShape::Hex: return 8;
    case ElementShape::Wedge: return 6;
    case ElementShape::Pyramid: return 5;
    case ElementShape::Quad: return 4;
    case ElementShape::Tri: return 3;
    case ElementShape::Unknown: break;
  }
  return 0;
}

bool isPlanarShape(ElementShape shape) { return shape == ElementShape::Quad || shape == ElementShape::Tri; }

ElementGeometry elementGeometry(ElementShape shape, const double* corners) {
  switch (shape) {
    case ElementShape::Tet: return tet(corners);
    case ElementShape::Hex: return hex(corners);
    case ElementShape::Wedge: return fanned(corners, 6, kWedgeFaces);
    case ElementShape::Pyramid: return fanned(corners, 5, kPyramidFaces);
    case ElementShape::Quad: return polygon(corners, 4);
    case ElementShape::Tri: return polygon(corners, 3);
    case ElementShape::Sphere:
    case ElementShape::Unknown: break;
  }
  throw std::logic_error("elementGeometry: no geometry for this element shape");
}

}  // namespace pf
