#pragma once
// Builds the point cloud from a validated DiscretizationSpec: Peridigm's PdQuickGrid and Text File, and
// Periforge's "Rectangle With Holes" (2D) and "Box With Holes" (3D) generators with optional fictitious
// boundary layers, "Cylinder" (CylinderGenerator.hpp), Peridigm's "Exodus" meshes (ExodusMesh.hpp) and Gmsh's
// (GmshMesh.hpp). A rank builds one slab of the cloud order (part
// `part` of `parts`), never the whole; a Text File is read in byte ranges. Bad mesh files are InputErrors.
#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/InfluenceFunction.hpp"
#include "input/Deck.hpp"

namespace pf {

struct PointCloud {                     // some points of the cloud (a slab, a rank's share, or all of it)
  std::vector<int> gid;                 // per point: its index in the cloud order (0-based), ascending
  long long numGlobal = 0;              // points in the whole cloud
  std::vector<double> x;                // 3 per point; 2D clouds have z = 0
  std::vector<double> volume;           // per point (2D: dx*dy*thickness)
  std::vector<int> block;               // 1-based block id per point ("block_1" -> 1)
  bool planar = false;
  double thickness = 0.0;               // 2D generators set these
  std::map<std::string, std::vector<int>> generatedNodeSets;  // gids of the held points, e.g. "Left Layer"
  double spacing = 0.0;                 // grid spacing if uniform (for messages/defaults), else 0
  Influence influence = Influence::One; // "Influence Function" of the Discretization list
  std::array<double, 3> cell{};         // grid cell edges of regular grids (0: flat axis or no grid)
  bool partialVolume = false;           // "Partial Volume": bonds weighted by the cell share in the horizon
  int size() const { return (int)volume.size(); }
};

// Receives a generator's points in cloud order and keeps those with index in [lo, hi) (gids set); next:
// the index of the next point, so after a whole pass it is the cloud's size. push returns whether it kept.
struct PointSink {
  PointCloud& cloud;
  long long lo, hi, next = 0;
  bool push(double x, double y, double z, double volume, int block);
};

// Points [N*part/parts, N*(part+1)/parts) of the cloud's N (every point with part 0 of 1; Text File: see
// below). inputFile names the deck in error messages (a mesh file's bad line, holes covering everything).
// Duplicate points are not looked for here (a slab cannot see them: DuplicatePoints.hpp).
PointCloud buildDiscretization(const DiscretizationSpec& spec, const std::string& inputFile, int part = 0,
                               int parts = 1);

// A Text File mesh, read by part `part` of `parts` without anyone reading the whole file: the byte range
// [begin, end) holds whole lines (it starts after a newline), `lines` newlines. readMeshRange parses that
// range, its first line being line firstLine + 1 of the file (in messages); gids are left to the caller.
struct MeshFileRange {
  long long begin = 0, end = 0, lines = 0;
};
MeshFileRange meshFileRange(const DiscretizationSpec& spec, const std::string& inputFile, int part, int parts);
PointCloud readMeshRange(const DiscretizationSpec& spec, const std::string& inputFile, const MeshFileRange& range,
                         long long firstLine);

// Reads a data file (mesh or node-set ids): calls use(text, where) for every line that is not blank
// once '#' comments are cut, where = "full:line". A file that cannot be opened is an InputError
// "inputFile: path: cannot open <what> file 'full'".
void forEachDataLine(const std::string& full, const std::string& inputFile, const std::string& path,
                     const std::string& what,
                     const std::function<void(const std::string& text, const std::string& where)>& use);

}  // namespace pf
