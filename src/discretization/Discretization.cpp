#include "Discretization.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/InputError.hpp"
#include "input/InputSchema.hpp"

namespace pf {

using PL = Teuchos::ParameterList;

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

PointCloud quickGrid(const PL& d, const std::string& file) {
  const std::string path = "Discretization/TensorProduct3DMeshGenerator";
  if (!d.isSublist("TensorProduct3DMeshGenerator")) fail(file, "Discretization", "missing sub-list 'TensorProduct3DMeshGenerator'");
  const PL& g = d.sublist("TensorProduct3DMeshGenerator");
  std::array<double, 3> o{}, h{};
  std::array<int, 3> n{};
  const char* ax[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a) {
    o[a] = getNumber(g, std::string(ax[a]) + " Origin");
    const double len = getNumber(g, std::string(ax[a]) + " Length");
    n[a] = getInteger(g, std::string("Number Points ") + ax[a], 0);
    if (!(len > 0.0)) fail(file, path, std::string("'") + ax[a] + " Length' must be positive (got " + num(len) + ")");
    if (n[a] < 1) fail(file, path, std::string("'Number Points ") + ax[a] + "' must be at least 1");
    h[a] = len / n[a];
  }
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

PointCloud textFile(const PL& d, const std::string& file, const std::string& dir) {
  const std::string path = "Discretization/Input Mesh File";
  const std::string name = getText(d, "Input Mesh File", "");
  const std::string full = resolvePath(name, dir);
  PointCloud c;
  forEachDataLine(full, file, path, "mesh", [&](const std::string& line, const std::string& where) {
    std::istringstream ss(line);
    double x, y, z, v;
    long b;
    std::string extra;
    if (!(ss >> x >> y >> z >> b >> v) || (ss >> extra))
      fail(file, path, where + ": expected 'x y z block_id volume', got '" + line + "'");
    if (b < 1) fail(file, path, where + ": block_id must be a positive integer (got " + std::to_string(b) + ")");
    if (!(v > 0.0) || !std::isfinite(v)) fail(file, path, where + ": volume must be positive (got " + num(v) + ")");
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) fail(file, path, where + ": non-finite coordinate");
    pushPoint(c, x, y, z, v, static_cast<int>(b));
  });
  if (c.size() == 0) fail(file, path, "mesh file '" + full + "' holds no points");
  return c;
}

struct Hole {
  std::array<double, 3> centre, axis;  // axis is a unit vector
  double radius;
};

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
bool insideAnyHole(const std::vector<Hole>& holes, double x, double y, double z) {
  for (const Hole& h : holes) {
    const double d[3] = {x - h.centre[0], y - h.centre[1], z - h.centre[2]};
    const double along = d[0] * h.axis[0] + d[1] * h.axis[1] + d[2] * h.axis[2];
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along;
    if (r2 < h.radius * h.radius * (1.0 - 1e-12)) return true;
  }
  return false;
}

PointCloud generator(const PL& d, const std::string& file, double defaultLayerWidth, bool box) {
  const double dx = getNumber(d, "Spacing");
  if (!(dx > 0.0)) fail(file, "Discretization", "'Spacing' must be positive (got " + num(dx) + ")");
  const bool nodes = getText(d, "Grid", "Cell Centers") == "Nodes";
  std::array<std::vector<double>, 3> line;
  const char* ax[3] = {"X", "Y", "Z"};
  for (int a = 0; a < (box ? 3 : 2); ++a) {
    const std::string L = std::string(ax[a]) + " Length";
    const double len = getNumber(d, L);
    if (!(len > 0.0)) fail(file, "Discretization", "'" + L + "' must be positive (got " + num(len) + ")");
    line[a] = gridLine(getNumber(d, std::string(ax[a]) + " Origin", 0.0), len, dx, nodes, file, L);
  }
  if (!box) line[2] = {0.0};

  PointCloud c;
  c.spacing = dx;
  c.cell = {dx, dx, box ? dx : 0.0};
  double vol = dx * dx * dx;
  if (!box) {
    c.planar = true;
    c.thickness = getNumber(d, "Thickness");
    if (!(c.thickness > 0.0))
      fail(file, "Discretization", "'Thickness' must be positive (got " + num(c.thickness) + ")");
    vol = dx * dx * c.thickness;
  }

  std::vector<Hole> holes;
  if (d.isSublist("Holes")) {
    const PL& hl = d.sublist("Holes");
    for (auto it = hl.begin(); it != hl.end(); ++it) {
      const std::string hpath = "Discretization/Holes/" + hl.name(it);
      if (!hl.entry(it).isList()) fail(file, "Discretization/Holes", "'" + hl.name(it) + "' is not a sub-list");
      const PL& h = hl.sublist(hl.name(it));
      Hole hole;
      hole.centre = {getNumber(h, "X Center"), getNumber(h, "Y Center"), box ? getNumber(h, "Z Center", 0.0) : 0.0};
      hole.radius = getNumber(h, "Radius");
      if (!(hole.radius > 0.0)) fail(file, hpath, "'Radius' must be positive (got " + num(hole.radius) + ")");
      hole.axis = {0.0, 0.0, 1.0};
      const std::string a = box ? getText(h, "Axis", "z") : "z";
      if (a == "x") hole.axis = {1.0, 0.0, 0.0};
      else if (a == "y") hole.axis = {0.0, 1.0, 0.0};
      else if (a != "z") {
        const std::vector<std::string> w = splitWords(a);
        double n2 = 0.0;
        try {
          if (w.size() != 3) throw std::invalid_argument("count");
          for (int k = 0; k < 3; ++k) {
            hole.axis[k] = std::stod(w[k]);
            n2 += hole.axis[k] * hole.axis[k];
          }
        } catch (const std::exception&) {
          n2 = 0.0;
        }
        if (!(n2 > 0.0)) fail(file, hpath, "'Axis' must be x, y, z or three numbers, not all zero (got '" + a + "')");
        for (double& v : hole.axis) v /= std::sqrt(n2);
      }
      holes.push_back(hole);
    }
  }

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

  const std::vector<std::string> faces = splitWords(getText(d, "Fictitious Layers", ""));
  if (!faces.empty()) {
    const double width = getNumber(d, "Layer Width", defaultLayerWidth);
    if (!(width > 0.0))
      fail(file, "Discretization", "'Layer Width' must be positive (give it, or a block 'Horizon' to default to)");
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
      else fail(file, "Discretization", "'Fictitious Layers' names unknown face '" + f + "'");
      std::vector<double> pos;
      if (low)
        for (long k = rows; k >= 1; --k) pos.push_back(line[a].front() - k * dx);
      else
        for (long k = 1; k <= rows; ++k) pos.push_back(line[a].back() + k * dx);
      std::array<std::vector<double>, 3> l = line;
      l[a] = pos;
      std::vector<int>& members = c.generatedNodeSets[f + " Layer"];
      if (!members.empty()) fail(file, "Discretization", "'Fictitious Layers' names face '" + f + "' twice");
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

std::string resolvePath(const std::string& name, const std::string& inputDir) {
  if (name.empty() || name[0] == '/' || inputDir.empty() || inputDir == ".") return name;
  return inputDir + "/" + name;
}

PointCloud buildDiscretization(const PL& d, const std::string& inputFile, const std::string& inputDir) {
  return buildDiscretization(d, inputFile, inputDir, 0.0);
}

PointCloud buildDiscretization(const PL& d, const std::string& inputFile, const std::string& inputDir,
                               double defaultLayerWidth) {
  const std::string type = getText(d, "Type", "");
  PointCloud c;
  if (type == "PdQuickGrid") c = quickGrid(d, inputFile);
  else if (type == "Text File") c = textFile(d, inputFile, inputDir);
  else if (type == "Rectangle With Holes") c = generator(d, inputFile, defaultLayerWidth, false);
  else if (type == "Box With Holes") c = generator(d, inputFile, defaultLayerWidth, true);
  else fail(inputFile, "Discretization", "unknown 'Type' = '" + type + "'");
  c.influence = influenceFromName(getText(d, "Influence Function", "One"), inputFile + ": Discretization");
  c.partialVolume = d.isParameter("Partial Volume") && d.get<bool>("Partial Volume");
  if (c.partialVolume && !(c.cell[0] > 0.0))
    fail(inputFile, "Discretization", "'Partial Volume' needs a regular grid; this discretization has no cells");
  if (c.size() == 0) fail(inputFile, "Discretization", "the discretization has no points (holes cover everything)");
  return c;
}

}  // namespace pf
