#include "Discretization.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <sstream>

#include "CylinderGenerator.hpp"
#include "ExodusMesh.hpp"
#include "GmshMesh.hpp"
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

}  // namespace

bool PointSink::push(double x, double y, double z, double v, int block) {
  const bool keep = next >= lo && next < hi;
  if (keep) {
    pushPoint(cloud, x, y, z, v, block);
    cloud.gid.push_back(static_cast<int>(next));
  }
  ++next;
  return keep;
}

namespace {

void quickGrid(const DiscretizationSpec& d, PointSink& sink) {
  PointCloud& c = sink.cloud;
  std::array<double, 3> o = d.origin, h{};
  std::array<int, 3> n = d.count;
  for (int a = 0; a < 3; ++a) h[a] = d.length[a] / n[a];
  const double vol = h[0] * h[1] * h[2];
  // x fastest, then y, then z: Peridigm's global ids (index + 1) and node sets depend on this order.
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        sink.push(o[0] + (i + 0.5) * h[0], o[1] + (j + 0.5) * h[1], o[2] + (k + 0.5) * h[2], vol, 1);
  const double tol = 1e-12 * std::max({h[0], h[1], h[2]});
  c.spacing = (std::fabs(h[0] - h[1]) <= tol && std::fabs(h[0] - h[2]) <= tol) ? h[0] : 0.0;
  c.cell = h;
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

void generator(const DiscretizationSpec& d, const std::string& file, PointSink& sink) {
  const bool box = d.type == DiscretizationSpec::Type::BoxWithHoles;
  const double dx = d.spacing;
  const bool nodes = d.gridNodes;
  std::array<std::vector<double>, 3> line;
  const char* ax[3] = {"X", "Y", "Z"};
  for (int a = 0; a < (box ? 3 : 2); ++a)
    line[a] = gridLine(d.origin[a], d.length[a], dx, nodes, file, std::string(ax[a]) + " Length");
  if (!box) line[2] = {0.0};

  PointCloud& c = sink.cloud;
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
          const long long id = sink.next;
          if (sink.push(x, y, z, vol, 1) && members) members->push_back(static_cast<int>(id));
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
}

}  // namespace

namespace {

// Cuts a '#' comment off line; false when nothing but blanks is left (a line that holds no data).
bool keepData(std::string& line) {
  const std::size_t hash = line.find('#');
  if (hash != std::string::npos) line.erase(hash);
  return line.find_first_not_of(" \t\r") != std::string::npos;
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
    if (!keepData(line)) continue;
    use(line, full + ":" + std::to_string(lineNo));
  }
}

namespace {

// One mesh line "x y z block_id volume" onto the cloud; where: "file:line" for messages.
void parseMeshLine(const std::string& line, const std::string& where, const std::string& file, PointCloud& c) {
  const std::string path = "Discretization/Input Mesh File";
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
}

std::ifstream openMesh(const DiscretizationSpec& d, const std::string& inputFile) {
  std::ifstream in(d.meshFile, std::ios::binary);
  if (!in) fail(inputFile, "Discretization/Input Mesh File", "cannot open mesh file '" + d.meshFile + "'");
  return in;
}

// The first line start at or after byte b (b itself if b is 0 or follows a newline).
long long lineStartFrom(std::ifstream& in, long long b, long long size) {
  if (b <= 0) return 0;
  if (b >= size) return size;
  in.clear();
  in.seekg(b - 1);
  char ch;
  while (in.get(ch))
    if (ch == '\n') return static_cast<long long>(in.tellg());
  return size;
}

}  // namespace

MeshFileRange meshFileRange(const DiscretizationSpec& d, const std::string& inputFile, int part, int parts) {
  std::ifstream in = openMesh(d, inputFile);
  in.seekg(0, std::ios::end);
  const long long size = static_cast<long long>(in.tellg());
  MeshFileRange r;
  r.begin = lineStartFrom(in, size * part / parts, size);
  r.end = lineStartFrom(in, size * (part + 1) / parts, size);
  in.clear();
  in.seekg(r.begin);
  std::vector<char> buf(1 << 16);
  for (long long left = r.end - r.begin; left > 0;) {
    in.read(buf.data(), static_cast<std::streamsize>(std::min<long long>(left, buf.size())));
    const std::streamsize got = in.gcount();
    if (got <= 0) break;
    r.lines += std::count(buf.begin(), buf.begin() + got, '\n');
    left -= got;
  }
  return r;
}

PointCloud readMeshRange(const DiscretizationSpec& d, const std::string& inputFile, const MeshFileRange& range,
                         long long firstLine) {
  std::ifstream in = openMesh(d, inputFile);
  in.seekg(range.begin);
  PointCloud c;
  std::string line;
  long long lineNo = firstLine;
  while (static_cast<long long>(in.tellg()) < range.end && std::getline(in, line)) {
    ++lineNo;
    if (!keepData(line)) continue;
    parseMeshLine(line, d.meshFile + ":" + std::to_string(lineNo), inputFile, c);
  }
  c.influence = d.influence;
  c.partialVolume = d.partialVolume;
  return c;
}

PointCloud buildDiscretization(const DiscretizationSpec& d, const std::string& inputFile, int part, int parts) {
  using T = DiscretizationSpec::Type;
  if (d.type == T::TextFile) {
    if (parts != 1) throw std::logic_error("buildDiscretization: a Text File slab needs meshFileRange/readMeshRange");
    PointCloud c = readMeshRange(d, inputFile, meshFileRange(d, inputFile, 0, 1), 0);
    if (c.size() == 0) fail(inputFile, "Discretization/Input Mesh File", "mesh file '" + d.meshFile + "' holds no points");
    c.numGlobal = c.size();
    c.gid.resize(c.size());
    for (int i = 0; i < c.size(); ++i) c.gid[i] = i;
    return c;
  }
  if (d.type == T::Exodus) return readExodusSlab(d, inputFile, part, parts);
  if (d.type == T::Gmsh) return readGmshSlab(d, inputFile, part, parts);
  // Two passes of the generator: the first counts the cloud, the second keeps this part's slab of it.
  auto run = [&](PointSink& sink) {
    switch (d.type) {
      case T::QuickGrid: quickGrid(d, sink); break;
      case T::RectangleWithHoles:
      case T::BoxWithHoles: generator(d, inputFile, sink); break;
      case T::Cylinder: cylinder(d, inputFile, sink); break;
      case T::TextFile:
      case T::Exodus:
      case T::Gmsh: break;
    }
  };
  PointCloud counted;
  PointSink count{counted, 0, 0};
  run(count);
  const long long n = count.next;
  if (n == 0) fail(inputFile, "Discretization", "the discretization has no points (holes cover everything)");
  if (n > INT_MAX) fail(inputFile, "Discretization", "the discretization has " + std::to_string(n) +
                                                         " points, more than 2147483647 (ids are ints)");
  PointCloud c;
  PointSink keep{c, n * part / parts, n * (part + 1) / parts};
  run(keep);
  c.numGlobal = n;
  c.influence = d.influence;
  c.partialVolume = d.partialVolume;
  return c;
}

}  // namespace pf
