// Bond filters (core/BondFilter.hpp) against hand-made segments whose answer is read off the drawing, and the
// binned BondCutter against the brute-force test of every polygon; the parsing of a Bond Filters list.
#include <gtest/gtest.h>

#include <random>

#include "core/BondFilter.hpp"
#include "discretization/BondCutter.hpp"
#include "test_input_helpers.hpp"

namespace {

using pf::Vec3;

bool cut(const pf::PlanePatch& s, Vec3 a, Vec3 b) { return pf::cuts(s, a.data(), b.data()); }
bool cut(const pf::DiskPatch& s, Vec3 a, Vec3 b) { return pf::cuts(s, a.data(), b.data()); }
bool cut(const pf::PolygonPatch& s, Vec3 a, Vec3 b) { return pf::cuts(s, a.data(), b.data()); }

// The rectangle 0 <= x <= 2, 0 <= z <= 3 in the plane y = 0: normal +y, bottom edge +x, so the side edge runs
// along bottom x normal = x x y = +z.
pf::PlanePatch rectangle() {
  pf::PlanePatch p;
  p.normal = {0, 1, 0};
  p.corner = {0, 0, 0};
  p.bottom = {1, 0, 0};
  p.bottomLength = 2.0;
  p.sideLength = 3.0;
  return p;
}

TEST(BondFilterPlane, CrossingInsideIsCutOutsideIsNot) {
  const pf::PlanePatch p = rectangle();
  EXPECT_TRUE(cut(p, {1, -1, 1}, {1, 1, 1}));
  EXPECT_TRUE(cut(p, {1, 1, 1}, {1, -1, 1}));      // either direction
  EXPECT_TRUE(cut(p, {0.5, -1, 0.5}, {1.5, 1, 2}));  // oblique, meets the plane at (1, 0, 1.25)
  EXPECT_FALSE(cut(p, {3, -1, 1}, {3, 1, 1}));     // beyond the bottom edge's length
  EXPECT_FALSE(cut(p, {1, -1, 3.5}, {1, 1, 3.5}));  // beyond the side edge's length
  EXPECT_FALSE(cut(p, {1, -1, -1}, {1, 1, -1}));   // the side runs along +z (bottom x normal), not -z
  EXPECT_FALSE(cut(p, {1, 0.5, 1}, {1, 2, 1}));    // segment ends before the plane
}

TEST(BondFilterPlane, ParallelIsNeverCutEvenInThePlane) {
  const pf::PlanePatch p = rectangle();
  EXPECT_FALSE(cut(p, {1, 0.5, 1}, {1.5, 0.5, 1}));
  EXPECT_FALSE(cut(p, {0.5, 0, 1}, {1.5, 0, 1}));  // lying in the rectangle: (p1 - p0).n = 0
}

TEST(BondFilterPlane, EdgesAndEndsOnThePlaneAreClosed) {
  // Peridigm's FinitePlane::bondIntersect keeps a meeting point with coordinates in (-1e-15, 1 + 1e-15) of each
  // edge: a bond through an edge or a corner is cut; one just beyond it is not.
  const pf::PlanePatch p = rectangle();
  EXPECT_TRUE(cut(p, {0, -1, 1}, {0, 1, 1}));   // through the left edge x = 0
  EXPECT_TRUE(cut(p, {2, -1, 1}, {2, 1, 1}));   // through the right edge x = 2
  EXPECT_TRUE(cut(p, {1, -1, 3}, {1, 1, 3}));   // through the top edge z = 3
  EXPECT_TRUE(cut(p, {0, -1, 0}, {0, 1, 0}));   // through the corner
  EXPECT_FALSE(cut(p, {2 + 1e-9, -1, 1}, {2 + 1e-9, 1, 1}));
  EXPECT_FALSE(cut(p, {-1e-9, -1, 1}, {-1e-9, 1, 1}));
  // t in [0, 1] with both ends: a point on the plane loses its bonds that leave the plane.
  EXPECT_TRUE(cut(p, {1, 0, 1}, {1, 1, 1}));
  EXPECT_TRUE(cut(p, {1, -1, 1}, {1, 0, 1}));
}

TEST(BondFilterPlane, VectorsAreUsedAsGiven) {
  // Peridigm's PrecrackedPlateTwoCracks: bottom (1, 4, 0) with normal (0, 1, 0) in the plane y = 4 from the corner
  // (0, 4, -10), lengths 10 and 20. The side is (1, 4, 0) x (0, 1, 0) = (0, 0, 1); the coordinate along the bottom
  // of a point of the plane is (1, 4, 0).(x, 0, z + 10) = x: the crack covers 0 <= x <= 10, -10 <= z <= 10.
  pf::PlanePatch p;
  p.normal = {0, 1, 0};
  p.corner = {0, 4, -10};
  p.bottom = {1, 4, 0};
  p.bottomLength = 10.0;
  p.sideLength = 20.0;
  EXPECT_TRUE(cut(p, {5, 3, 0}, {5, 5, 0}));
  EXPECT_TRUE(cut(p, {9.5, 3, 9.5}, {9.5, 5, 9.5}));
  EXPECT_FALSE(cut(p, {-1, 3, 0}, {-1, 5, 0}));
  EXPECT_FALSE(cut(p, {5, 3, 10.5}, {5, 5, 10.5}));
}

TEST(BondFilterDisk, InsideIsCutTheRimIsNot) {
  const pf::DiskPatch d{{0, 0, 0}, {0, 1, 0}, 2.5};
  EXPECT_TRUE(cut(d, {1, -1, 0}, {1, 1, 0}));
  EXPECT_TRUE(cut(d, {0, 1, 0}, {0, -1, 0}));
  EXPECT_FALSE(cut(d, {2.5, -1, 0}, {2.5, 1, 0}));  // on the rim: Peridigm's |x - c|^2 < r^2 is strict
  EXPECT_FALSE(cut(d, {2.6, -1, 0}, {2.6, 1, 0}));
  EXPECT_FALSE(cut(d, {1, 0.5, 0}, {1, 2, 0}));     // ends before the plane
  EXPECT_FALSE(cut(d, {1, 0, 0}, {2, 0, 0}));       // in the disk's plane: parallel
}

TEST(BondFilterPolygon, TriangleAndQuad) {
  pf::PolygonPatch tri, quad;
  ASSERT_TRUE(pf::makePolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, tri));
  ASSERT_TRUE(pf::makePolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, quad));
  EXPECT_TRUE(cut(tri, {0.2, 0.2, -1}, {0.2, 0.2, 1}));
  EXPECT_FALSE(cut(tri, {0.6, 0.6, -1}, {0.6, 0.6, 1}));
  EXPECT_TRUE(cut(tri, {0.5, 0.5, -1}, {0.5, 0.5, 1}));  // on the hypotenuse: edges closed
  EXPECT_TRUE(cut(tri, {0, 0, -1}, {0, 0, 1}));          // a corner
  EXPECT_FALSE(cut(tri, {0.2, 0.2, 0.5}, {0.2, 0.2, 1}));
  EXPECT_TRUE(cut(quad, {0.9, 0.1, -1}, {0.9, 0.1, 1}));  // the half v0 v1 v2
  EXPECT_TRUE(cut(quad, {0.1, 0.9, -1}, {0.1, 0.9, 1}));  // the half v0 v2 v3
  EXPECT_TRUE(cut(quad, {0.6, 0.6, -1}, {0.6, 0.6, 1}));
  EXPECT_FALSE(cut(quad, {1.1, 0.5, -1}, {1.1, 0.5, 1}));
  EXPECT_FALSE(cut(quad, {0.5, 0.5, 0}, {0.7, 0.5, 0}));  // in the quad's plane
  pf::PolygonPatch flat;
  EXPECT_FALSE(pf::makePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, flat));  // zero area
}

// The binned cutter gives the brute-force answer: a mesh of 8 x 8 quads and triangles spread over a tilted surface
// inside a cloud, random bonds up to the reach.
TEST(BondFilterCutter, BinningMatchesEveryPolygon) {
  pf::BondFilters f;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double x0 = 0.25 * i, y0 = 0.25 * j, x1 = x0 + 0.25, y1 = y0 + 0.25;
      auto z = [](double x, double y) { return 0.8 + 0.1 * x - 0.05 * y; };
      pf::PolygonPatch p;
      if ((i + j) % 2)
        ASSERT_TRUE(pf::makePolygon({{x0, y0, z(x0, y0)}, {x1, y0, z(x1, y0)}, {x1, y1, z(x1, y1)}, {x0, y1, z(x0, y1)}}, p));
      else
        ASSERT_TRUE(pf::makePolygon({{x0, y0, z(x0, y0)}, {x1, y0, z(x1, y0)}, {x1, y1, z(x1, y1)}}, p));
      f.polygons.push_back(p);
    }
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-0.2, 2.2), step(-0.3, 0.3);
  std::vector<double> pts;
  for (int k = 0; k < 4000; ++k) {
    const double a[3] = {u(gen), u(gen), 0.4 * u(gen)};
    pts.insert(pts.end(), {a[0], a[1], a[2], a[0] + step(gen), a[1] + step(gen), a[2] + step(gen)});
  }
  const pf::BondCutter cutter(f, pts, 0.6);
  int cuts = 0;
  for (std::size_t k = 0; k < pts.size(); k += 6) {
    bool brute = false;
    for (const pf::PolygonPatch& p : f.polygons) brute = brute || pf::cuts(p, &pts[k], &pts[k + 3]);
    EXPECT_EQ(cutter.cuts(&pts[k], &pts[k + 3]), brute) << "bond " << k / 6;
    cuts += brute;
  }
  EXPECT_GT(cuts, 100);  // the sample crosses the surface often enough to test something
}

}  // namespace

namespace {

// A bad filter is one InputError naming the deck and the filter's parameter.
std::string discretizationWith(const std::string& filter) {
  return "<ParameterList name=\"Discretization\"><Parameter name=\"Type\" type=\"string\" value=\"PdQuickGrid\"/>"
         "<ParameterList name=\"TensorProduct3DMeshGenerator\">"
         "<Parameter name=\"X Origin\" type=\"double\" value=\"0\"/><Parameter name=\"Y Origin\" type=\"double\" value=\"0\"/>"
         "<Parameter name=\"Z Origin\" type=\"double\" value=\"0\"/><Parameter name=\"X Length\" type=\"double\" value=\"1\"/>"
         "<Parameter name=\"Y Length\" type=\"double\" value=\"1\"/><Parameter name=\"Z Length\" type=\"double\" value=\"1\"/>"
         "<Parameter name=\"Number Points X\" type=\"int\" value=\"2\"/><Parameter name=\"Number Points Y\" type=\"int\" value=\"2\"/>"
         "<Parameter name=\"Number Points Z\" type=\"int\" value=\"2\"/></ParameterList>"
         "<ParameterList name=\"Bond Filters\"><ParameterList name=\"F\">" + filter + "</ParameterList></ParameterList>"
         "</ParameterList>";
}

std::string param(const std::string& name, const std::string& type, const std::string& value) {
  return "<Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>";
}

std::string disk(double nx, double radius) {
  return param("Type", "string", "Disk") + param("Center_X", "double", "0") + param("Center_Y", "double", "0") +
         param("Center_Z", "double", "0") + param("Normal_X", "double", std::to_string(nx)) +
         param("Normal_Y", "double", "0") + param("Normal_Z", "double", "0") +
         param("Radius", "double", std::to_string(radius));
}

pf::DiscretizationSpec parse(const std::string& filter) {
  return pf::parseDiscretization(*pftest::deckFromXml(discretizationWith(filter)), "deck.xml", ".");
}

TEST(BondFilterInput, ParsedOnceIntoTheSpec) {
  const pf::DiscretizationSpec s = parse(disk(1.0, 0.3));
  ASSERT_EQ(s.bondFilters.disks.size(), 1u);
  EXPECT_EQ(s.bondFilters.disks[0].radius, 0.3);
  EXPECT_TRUE(s.bondFilters.planes.empty());
}

TEST(BondFilterInput, BadFiltersAreInputErrors) {
  EXPECT_INPUT_ERROR(parse(param("Type", "string", "Sphere")), "deck.xml", "Discretization/Bond Filters/F");
  EXPECT_INPUT_ERROR(parse(disk(0.0, 0.3)), "deck.xml", "Normal_X");
  EXPECT_INPUT_ERROR(parse(disk(1.0, -0.3)), "deck.xml", "Radius");
  EXPECT_INPUT_ERROR(parse(disk(1.0, 0.3) + param("Side_Length", "double", "1")), "deck.xml", "Side_Length");
  EXPECT_INPUT_ERROR(parse(param("Type", "string", "Exodus Mesh") + param("File Name", "string", "no_such.g")),
                     "deck.xml", "Discretization/Bond Filters/F/File Name");
}

}  // namespace
