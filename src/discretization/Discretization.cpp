#include "Discretization.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <fstream>
#include <sstream>

#include "CylinderGenerator.hpp"
#include "DuplicatePoints.hpp"
#include "core/InputError.hpp"
#include "core/Words.hpp"

namespace pf {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& msg) {
  throw InputError(file + ": " + path + ": " + msg);
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void pushPoint(PointCloud& c, double x, double y, double z, double v, int block) {
  c.x.push_back(x);
  c.x.push_back(y);
  c.x.push_back(z);
  c.volume.push_back(v);
  c.block.push_back(block);
}

PointCloud quickGrid(const DiscretizationSpec& d) {
  std::array<double, 3> o = d.origin, h{};
  std::array<int, 3> n = d.count;
  for (int a = 0; a < 3; ++a) h[a] = d.length[a] / n[a];
  PointCloud c;
  const double vol = h[0] * h[1] * h[2];
  const std::size_t total = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  c.x.reserve(3 * total);
  c.volume.reserve(total);
  c.block.reserve(total);
  // x fastest, then y, then z: Peridigm's global ids (index + 1) and node sets depend on this order.
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        pushPoint(c, o[0] + (i + 0.5) * h[0], o[1] + (j + 0.5) * h[1], o[2] + (k + 0.5) * h[2], vol, 1);
  const double tol = 1e-12 * std::max({h[0], h[1], h[2]});
  c.spacing = (std::fabs(h[0] - h[1]) <= tol && std::fabs(h[0] - h[2]) <= tol) ? h[0] : 0.0;
  c.cell = h;
  return c;
}

PointCloud textFile(const DiscretizationSpec& d, const std::string& file) {
  const std::string path = "Discretization/Input Mesh File";
  const std::string& full = d.meshFile;
  PointCloud c;
  forEachDataLine(full, file, path, "mesh", [&](const std::string& line, const std::string& where) {
    std::istringstream ss(line);
    double x, y, z, v;
    long b;
    std::string extra;
    if (!(ss >> x >> y >> z >> b >> v) || (ss >> extra))
      fail(file, path, where + ": expected 'x y z block_id volume', got '" + printable(line) + "'");
    if (b < 1 || b > INT_MAX)  // (an id past an int would wrap into another block's)
      fail(file, path, where + ": block_id must be a positive integer up to 2147483647 (got " + std::to_string(b) + ")");
    if (!(v > 0.0) || !std::isfinite(v)) fail(file, path, where + ": volume must be positive (got " + num(v) + ")");
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) fail(file, path, where + ": non-finite coordinate");
    pushPoint(c, x, y, z, v, static_cast<int>(b));
  });
  if (c.size() == 0) fail(file, path, "mesh file '" + full + "' holds no points");
  return c;
}

std::vector<double> gridLine(double origin, double length, double dx, bool nodes, const std::string& file,
                             const std::string& lengthName) {
  const double ratio = length / dx;
  const long n = std::lround(ratio);
  if (n < 1 || std::fabs(ratio - n) > 1e-6 * std::max(1.0, ratio))
    fail(file, "Discretization", "'" + lengthName + "' (" + num(length) + ") is not a multiple of 'Spacing' (" +
                                     num(dx) + ")");
  std::vector<double> c;
  if (nodes)
    for (long i = 0; i <= n; ++i) c.push_back(origin + i * dx);
  else
    for (long i = 0; i < n; ++i) c.push_back(origin + (i + 0.5) * dx);
  return c;
}

// Points on a circle/cylinder surface are kept: the relative slack stops round-off from deciding.
bool insideAnyHole(const std::vector<HoleSpec>& holes, double x, double y, double z) {
  for (const HoleSpec& h : holes) {
    const double d[3] = {x - h.centre[0], y - h.centre[1], z - h.centre[2]};
    const double along = d[0] * h.axis[0] + d[1] * h.axis[1] + d[2] * h.axis[2];
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along;
    if (r2 < h.radius * h.radius * (1.0 - 1e-12)) return true;
  }
  return false;
}

PointCloud generator(const DiscretizationSpec& d, const std::string& file) {
  const bool box = d.type == DiscretizationSpec::Type::BoxWithHoles;
  const double dx = d.spacing;
  const bool nodes = d.gridNodes;
  std::array<std::vector<double>, 3> line;
  const char* ax[3] = {"X", "Y", "Z"};
  for (int a = 0; a < (box ? 3 : 2); ++a)
    line[a] = gridLine(d.origin[a], d.length[a], dx, nodes, file, std::string(ax[a]) + " Length");
  if (!box) line[2] = {0.0};

  PointCloud c;
  c.spacing = dx;
  c.cell = {dx, dx, box ? dx : 0.0};
  double vol = dx * dx * dx;
  if (!box) {
    c.planar = true;
    c.thickness = d.thickness;
    vol = dx * dx * c.thickness;
  }
  const std::vector<HoleSpec>& holes = d.holes;

  auto addBlock = [&](const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& zs,
                      std::vector<int>* members) {
    for (double z : zs)
      for (double y : ys)
        for (double x : xs) {
          if (insideAnyHole(holes, x, y, z)) continue;
          if (members) members->push_back(c.size());
          pushPoint(c, x, y, z, vol, 1);
        }
  };
  addBlock(line[0], line[1], line[2], nullptr);

  const std::vector<std::string>& faces = d.layers;
  if (!faces.empty()) {
    const double width = d.layerWidth;
    // The layer covers at least its width: a partial row still counts as a row.
    const long rows = std::max(1L, static_cast<long>(std::ceil(width / dx - 1e-9)));
    for (const std::string& f : faces) {
      int a = -1;
      bool low = true;
      if (f == "Left") a = 0;
      else if (f == "Right") a = 0, low = false;
      else if (f == "Bottom") a = 1;
      else if (f == "Top") a = 1, low = false;
      else if (f == "Back" && box) a = 2;
      else if (f == "Front" && box) a = 2, low = false;
      else continue;  // not a face of this generator: refused by the input layer
      std::vector<double> pos;
      if (low)
        for (long k = rows; k >= 1; --k) pos.push_back(line[a].front() - k * dx);
      else
        for (long k = 1; k <= rows; ++k) pos.push_back(line[a].back() + k * dx);
      std::array<std::vector<double>, 3> l = line;
      l[a] = pos;
      std::vector<int>& members = c.generatedNodeSets[f + " Layer"];
      addBlock(l[0], l[1], l[2], &members);
    }
  }
  return c;
}

}  // namespace

void forEachDataLine(const std::string& full, const std::string& inputFile, const std::string& path,
                     const std::string& what,
                     const std::function<void(const std::string& text, const std::string& where)>& use) {
  std::ifstream in(full);
  if (!in) fail(inputFile, path, "cannot open " + what + " file '" + full + "'");
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    use(line, full + ":" + std::to_string(lineNo));
  }
}

PointCloud buildDiscretization(const DiscretizationSpec& d, const std::string& inputFile) {
  using T = DiscretizationSpec::Type;
  PointCloud c;
  switch (d.type) {
    case T::QuickGrid: c = quickGrid(d); break;
    case T::TextFile: c = textFile(d, inputFile); break;
    case T::RectangleWithHoles:
    case T::BoxWithHoles: c = generator(d, inputFile); break;
    case T::Cylinder: c = cylinder(d, inputFile); break;
  }
  c.influence = d.influence;
  c.partialVolume = d.partialVolume;
  if (c.size() == 0) fail(inputFile, "Discretization", "the discretization has no points (holes cover everything)");
  requireDistinctPoints(c, inputFile);
  return c;
}

}  // namespace pf
