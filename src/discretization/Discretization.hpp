#pragma once
// Builds the point cloud from a validated DiscretizationSpec: Peridigm's PdQuickGrid and Text File, and
// Periforge's "Rectangle With Holes" (2D) and "Box With Holes" (3D) generators with optional fictitious
// boundary layers, and "Cylinder" (CylinderGenerator.hpp). Every rank builds the same cloud in the same
// order; bad mesh files are InputErrors.
#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/InfluenceFunction.hpp"
#include "input/Deck.hpp"

namespace pf {

struct PointCloud {                     // every rank builds the same cloud, deterministically
  std::vector<double> x;                // 3 per point; 2D clouds have z = 0
  std::vector<double> volume;           // per point (2D: dx*dy*thickness)
  std::vector<int> block;               // 1-based block id per point ("block_1" -> 1)
  bool planar = false;
  double thickness = 0.0;               // 2D generators set these
  std::map<std::string, std::vector<int>> generatedNodeSets;  // 0-based, e.g. fictitious layer "Left Layer"
  double spacing = 0.0;                 // grid spacing if uniform (for messages/defaults), else 0
  Influence influence = Influence::One; // "Influence Function" of the Discretization list
  std::array<double, 3> cell{};         // grid cell edges of regular grids (0: flat axis or no grid)
  bool partialVolume = false;           // "Partial Volume": bonds weighted by the cell share in the horizon
  int size() const { return (int)volume.size(); }
};

// inputFile names the deck in error messages (a mesh file's bad line, holes covering everything).
PointCloud buildDiscretization(const DiscretizationSpec& spec, const std::string& inputFile);

// Reads a data file (mesh or node-set ids): calls use(text, where) for every line that is not blank
// once '#' comments are cut, where = "full:line". A file that cannot be opened is an InputError
// "inputFile: path: cannot open <what> file 'full'".
void forEachDataLine(const std::string& full, const std::string& inputFile, const std::string& path,
                     const std::string& what,
                     const std::function<void(const std::string& text, const std::string& where)>& use);

}  // namespace pf
