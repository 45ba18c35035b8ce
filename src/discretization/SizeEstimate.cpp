#include "SizeEstimate.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "CylinderGenerator.hpp"
#include "Discretization.hpp"
#include "ExodusMesh.hpp"
#include "GmshMesh.hpp"
#include "core/InputError.hpp"

namespace pf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A regular grid as the estimate sees it: cell edges (0: flat axis), points along each axis including
// fictitious layers (they bound the offsets a family can reach), and the number of points.
struct GridShape {
  std::array<double, 3> cell{};
  std::array<double, 3> extent{1.0, 1.0, 1.0};
  double points = 0.0;
};

GridShape quickGridShape(const DiscretizationSpec& d) {
  GridShape g;
  g.points = 1.0;
  for (int a = 0; a < 3; ++a) {
    g.cell[a] = d.length[a] / d.count[a];
    g.extent[a] = d.count[a];
    g.points *= d.count[a];
  }
  return g;
}

// Points of one grid line as Discretization's gridLine makes them (round(L/dx) cells; nodes add one).
double linePoints(double length, double dx, bool nodes) {
  return std::max(1.0, std::round(length / dx)) + (nodes ? 1.0 : 0.0);
}

int layerAxis(const std::string& face, bool box) {
  if (face == "Left" || face == "Right") return 0;
  if (face == "Bottom" || face == "Top") return 1;
  if (box && (face == "Back" || face == "Front")) return 2;
  return -1;
}

// The generators: the core grid, then per layer face rows x (the other two lines), as generator() adds them.
GridShape generatorShape(const DiscretizationSpec& d) {
  const bool box = d.type == DiscretizationSpec::Type::BoxWithHoles;
  GridShape g;
  std::array<double, 3> line{1.0, 1.0, 1.0};
  for (int a = 0; a < (box ? 3 : 2); ++a) {
    line[a] = linePoints(d.length[a], d.spacing, d.gridNodes);
    g.cell[a] = d.spacing;
  }
  g.extent = line;
  g.points = line[0] * line[1] * line[2];
  const double rows = std::max(1.0, std::ceil(d.layerWidth / d.spacing - 1e-9));
  for (const std::string& f : d.layers) {
    const int a = layerAxis(f, box);
    if (a < 0) continue;
    g.points += rows * line[0] * line[1] * line[2] / line[a];
    g.extent[a] += rows;
  }
  return g;
}

// The cylinder's lattice: its cross-section's points (as the generator makes them) times its layers.
GridShape cylinderShape(const DiscretizationSpec& d, const std::string& inputFile) {
  GridShape g;
  const double across = std::round(2.0 * d.radius / d.spacing), layers = cylinderLayers(d, inputFile);
  g.cell = {d.spacing, d.spacing, d.spacing};
  g.extent = {across, across, across};
  g.extent[d.cylinderAxis] = layers;
  // Enumerated up to 1024 across (a section of 0.8 million points at most); beyond, the disc's area over dx^2,
  // so that the guard refuses an absurd deck before the generator would allocate it.
  const double section = across <= 1024 ? static_cast<double>(cylinderSection(d, inputFile).size())
                                        : kPi * d.radius * d.radius / (d.spacing * d.spacing);
  g.points = section * layers;
  return g;
}

// Largest offset k >= 0 along one axis whose share of the distance still fits in rem (a squared length):
// centres |k c| (with the neighbour search's tie tolerance), or with partial volume the near face of the cell.
double maxOffset(double rem, double c, double extent, bool partialVolume) {
  if (!(c > 0.0) || extent <= 1.0 || rem < 0.0) return 0.0;
  const double r = std::sqrt(rem);
  // A cell that only touches the ball has no share in it (NeighborSearch drops fractions <= 1e-12);
  // a centre exactly on the horizon is a neighbour (its 1e-10 tie tolerance).
  const double k = partialVolume ? std::ceil(r / c * (1.0 - 1e-9) + 0.5) - 1.0 : std::floor(r / c * (1.0 + 1e-9));
  return std::min(k, extent - 1.0);
}

// The continuum count for radii too large to enumerate: the ball (grown by half a cell diagonal with
// partial volume) over the cell, within the box the grid spans.
double continuumFamily(const std::array<double, 3>& cell, const std::array<double, 3>& extent, double radius,
                       bool partialVolume) {
  double measure = 1.0, box = 1.0, half = 0.0;
  int dims = 0;
  for (int a = 0; a < 3; ++a)
    if (cell[a] > 0.0 && extent[a] > 1.0) {
      measure *= cell[a];
      box *= 2.0 * extent[a] - 1.0;
      half += 0.25 * cell[a] * cell[a];
      ++dims;
    }
  const double r = radius + (partialVolume ? std::sqrt(half) : 0.0);
  const double ball = dims == 3 ? 4.0 / 3.0 * kPi * r * r * r : dims == 2 ? kPi * r * r : 2.0 * r;
  return std::min(dims == 0 ? 0.0 : ball / measure, box - 1.0);
}

struct TextMeshScan {
  double points = 0.0, volume = 0.0;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
};

// One pass over the mesh file without storing it: count, total volume, bounding box. Malformed lines are
// skipped here (buildDiscretization reports them with their line number).
TextMeshScan scanMesh(const Deck& deck) {
  TextMeshScan s;
  forEachDataLine(deck.discretization.meshFile, deck.file, "Discretization/Input Mesh File", "mesh",
                  [&](const std::string& line, const std::string&) {
                    std::istringstream ss(line);
                    double x[3], v;
                    long b;
                    if (!(ss >> x[0] >> x[1] >> x[2] >> b >> v)) return;
                    s.points += 1.0;
                    s.volume += v;
                    for (int a = 0; a < 3; ++a) s.lo[a] = std::min(s.lo[a], x[a]), s.hi[a] = std::max(s.hi[a], x[a]);
                  });
  return s;
}

// A mesh file has no grid: the family is that of a cubic lattice with the mean cell volume, or for a flat
// mesh (all z equal) of a square lattice filling the bounding rectangle.
// An Exodus or Gmsh mesh: its element count and node box; the total volume is taken as the box's (an upper
// bound, so the estimate's spacing errs large and its family small for a body with holes).
TextMeshScan scanElementMesh(const Deck& deck) {
  const MeshExtent x = deck.discretization.type == DiscretizationSpec::Type::Gmsh
                           ? gmshExtent(deck.discretization, deck.file)
                           : exodusExtent(deck.discretization, deck.file);
  TextMeshScan s;
  s.points = static_cast<double>(x.elements);
  s.volume = 1.0;
  for (int a = 0; a < 3; ++a) {
    s.lo[a] = x.lo[a], s.hi[a] = x.hi[a];
    if (x.hi[a] > x.lo[a]) s.volume *= x.hi[a] - x.lo[a];
  }
  return s;
}

SizeEstimate meshFileEstimate(const Deck& deck) {
  const TextMeshScan s = deck.discretization.isElementMesh() ? scanElementMesh(deck) : scanMesh(deck);
  SizeEstimate e;
  e.points = s.points;
  e.meshFile = true;
  if (!(s.points > 1.0)) return e;
  const bool flat = !(s.hi[2] > s.lo[2]);
  const double area = (s.hi[0] - s.lo[0]) * (s.hi[1] - s.lo[1]);
  const double dx = flat ? std::sqrt(area / s.points) : std::cbrt(s.volume / s.points);
  if (!(dx > 0.0)) return e;
  const std::array<double, 3> cell{dx, dx, flat ? 0.0 : dx};
  std::array<double, 3> extent{};
  for (int a = 0; a < 3; ++a) extent[a] = std::round((s.hi[a] - s.lo[a]) / dx) + 1.0;
  e.family = latticeFamily(cell, extent, deck.maxHorizon(), deck.discretization.partialVolume);
  return e;
}

// Load times every rank holds: a step count materialises n + 1 of them (SolverInput).
double loadTimes(const Deck& deck) {
  double n = 0.0;
  for (const SolverSpec& s : deck.solvers) n += static_cast<double>(s.times.size());
  return n;
}

bool hasNewtonKrylov(const Deck& deck) {
  for (const SolverSpec& s : deck.solvers)
    if (s.type == "NOXQuasiStatic" || s.type == "QuasiStatic" || s.type == "Implicit") return true;
  return false;
}

}  // namespace

double latticeFamily(const std::array<double, 3>& cell, const std::array<double, 3>& extent, double radius,
                     bool partialVolume) {
  const double r2 = radius * radius * (partialVolume ? 1.0 : 1.0 + 1e-10);
  auto part = [&](double k, double c) {  // an offset's squared share of the distance along one axis
    const double d = partialVolume ? std::max(0.0, k * c - 0.5 * c) : k * c;
    return d * d;
  };
  const double imax = maxOffset(r2, cell[0], extent[0], partialVolume);
  const double jmax = maxOffset(r2, cell[1], extent[1], partialVolume);
  if ((2.0 * imax + 1.0) * (2.0 * jmax + 1.0) > 4.0e6) return continuumFamily(cell, extent, radius, partialVolume);
  // Columns along z: for each (i, j) inside the ball the k range follows from what is left of the radius.
  double count = 0.0;
  for (double i = 0.0; i <= imax; ++i) {
    const double ri = r2 - part(i, cell[0]);
    if (ri < 0.0) break;
    const double jm = maxOffset(ri, cell[1], extent[1], partialVolume);
    for (double j = 0.0; j <= jm; ++j) {
      const double rj = ri - part(j, cell[1]);
      if (rj < 0.0) break;
      const double column = 2.0 * maxOffset(rj, cell[2], extent[2], partialVolume) + 1.0;
      count += column * (i > 0.0 ? 2.0 : 1.0) * (j > 0.0 ? 2.0 : 1.0);
    }
  }
  return count - 1.0;  // a point is not its own neighbour
}

SizeEstimate estimateSize(const Deck& deck) {
  const DiscretizationSpec& d = deck.discretization;
  SizeEstimate e;
  if (d.type == DiscretizationSpec::Type::TextFile || d.isElementMesh()) {
    e = meshFileEstimate(deck);
  } else {
    const GridShape g = d.type == DiscretizationSpec::Type::QuickGrid ? quickGridShape(d)
                        : d.type == DiscretizationSpec::Type::Cylinder ? cylinderShape(d, deck.file)
                                                                        : generatorShape(d);
    e.points = g.points;
    e.holes = !d.holes.empty();
    e.family = latticeFamily(g.cell, g.extent, deck.maxHorizon(), d.partialVolume);
  }
  e.family = std::min(e.family, std::max(0.0, e.points - 1.0));
  e.bonds = e.points * e.family;
  e.loadTimes = loadTimes(deck);
  e.newtonKrylov = hasNewtonKrylov(deck);
  for (const BlockGroupSpec& b : deck.blocks) e.damage = e.damage || !b.damageModel.empty();
  return e;
}

MemoryModel memoryModel(const SizeEstimate& e) {
  // Least-squares fit (relative error) to peak RSS at np 1 of 8 Verlet decks (8e3-5e5 points, 2e6-6e7
  // bonds): every one within 0.2 %; the per-rank share of the cloud from two of them at np 2.
  const MemoryModel explicitSolvers{60.1e6, 90.0, 667.0, 36.0};
  // NOX adds what its peak depends on beyond points and bonds, taken at its worst: the whole GMRES basis
  // (201 vectors of 3 doubles per point at the default Krylov size 200, touched only as far as the solve
  // iterates) and the pair-stiffness matrix with its multigrid hierarchy (120 B per bond: 9 entries of 12 B,
  // and the hierarchy's share; fitted with ML's, still an upper bound with MueLu's: docs/benchmark-log.md, issue 20).
  // Measured runs use 0.46-1.0 of it, so it is an upper bound.
  const MemoryModel newton{60.1e6, 90.0, 667.0 + 201.0 * 3.0 * 8.0, 36.0 + 120.0};
  MemoryModel m = e.newtonKrylov ? newton : explicitSolvers;
  // Bond damage, counted not fitted: the broken flags' committed and trial copies (16 B per bond) and the
  // quasi-static break rounds' base copy (8 B; allocated by any solver list that is not Verlet: counted always).
  if (e.damage) m.perBond += 24.0;
  return m;
}

double bytesPerRank(const SizeEstimate& e, int np) {
  const MemoryModel m = memoryModel(e);
  const double p = std::max(1, np);
  return m.fixed + m.perRankPoint * e.points + (m.perPoint * e.points + m.perBond * e.bonds) / p +
         8.0 * e.loadTimes;
}

double bytesPerRun(const SizeEstimate& e, int np) { return std::max(1, np) * bytesPerRank(e, np); }

double availableMemory() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double value = 0.0;
  while (in >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024.0;  // the kernel reports kB (KiB)
  return 0.0;
}

std::string bytesText(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, units[u]);
  return buf;
}

void checkSize(const Deck& deck, const SizeEstimate& e, int np, double limit, const std::string& limitName) {
  const DiscretizationSpec& d = deck.discretization;
  const std::string change = d.type == DiscretizationSpec::Type::QuickGrid  ? "fewer 'Number Points'"
                             : d.type == DiscretizationSpec::Type::TextFile || d.isElementMesh()
                                   ? "a coarser mesh"
                                                                             : "a larger 'Spacing'";
  char counts[160];
  std::snprintf(counts, sizeof counts, "%.4g points, %.4g bonds (%.4g per point)", e.points, e.bonds, e.family);
  const std::string fix = "; use " + change + " or a smaller 'Horizon'";
  if (e.points > INT_MAX || e.bonds > INT_MAX)
    throw InputError(deck.file + ": Discretization: " + counts + " overflow 32-bit ids (at most " +
                     std::to_string(INT_MAX) + " each)" + fix);
  const double need = bytesPerRun(e, np);
  if (limit > 0.0 && need > limit)
    throw InputError(deck.file + ": Discretization: " + counts + " need about " + bytesText(need) + " at np " +
                     std::to_string(np) + ", more than " + limitName + " (" + bytesText(limit) + ")" + fix);
}

}  // namespace pf
