#include "ElementPoints.hpp"

#include <algorithm>
#include <sstream>

#include "core/InputError.hpp"

namespace pf {

void MeshElements::add(ElementShape s, int blockId, long long labelId, const long long* first, int count,
                       double sphere) {
  nodes.insert(nodes.end(), first, first + count);
  offset.push_back(static_cast<int>(nodes.size()));
  shape.push_back(s);
  block.push_back(blockId);
  label.push_back(labelId);
  sphereVolume.push_back(sphere);
}

MeshNodes::MeshNodes(const MeshElements& e) : ids(e.nodes) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  xyz.assign(3 * ids.size(), 0.0);
}

std::size_t MeshNodes::find(long long id) const {
  const auto it = std::lower_bound(ids.begin(), ids.end(), id);
  return it != ids.end() && *it == id ? static_cast<std::size_t>(it - ids.begin()) : ids.size();
}

PointCloud elementPoints(const MeshElements& e, const MeshNodes& n, long long firstIndex, long long numGlobal,
                         bool planar, const DiscretizationSpec& spec, const std::string& inputFile,
                         const std::function<void(const std::string&)>& fail) {
  if (planar && !(spec.thickness > 0.0))
    throw InputError(inputFile + ": Discretization/Thickness: the mesh '" + spec.meshFile +
                     "' has 2D elements (QUAD, TRI): give 'Thickness', the out-of-plane thickness");
  PointCloud c;
  c.numGlobal = numGlobal;
  c.influence = spec.influence;
  c.planar = planar;
  c.thickness = planar ? spec.thickness : 0.0;
  std::vector<double> corners;
  for (int k = 0; k < e.size(); ++k) {
    const int count = cornerNodes(e.shape[k]);
    corners.resize(3 * static_cast<std::size_t>(count));
    for (int m = 0; m < count; ++m) {
      const std::size_t at = n.find(e.nodes[e.offset[k] + m]);
      for (int i = 0; i < 3; ++i) corners[3 * m + i] = n.xyz[3 * at + i];
    }
    const bool sphere = e.shape[k] == ElementShape::Sphere;
    ElementGeometry g;
    if (sphere) {
      g.centroid = {corners[0], corners[1], corners[2]};
      g.measure = e.sphereVolume[k];
    } else {
      g = elementGeometry(e.shape[k], corners.data());
    }
    if (!(g.measure > 0.0)) {
      std::ostringstream measure;
      measure << g.measure;
      fail("element " + std::to_string(e.label[k]) + " (block " + std::to_string(e.block[k]) + ") has " +
           (sphere ? "volume attribute " : planar ? "area " : "volume ") + measure.str() +
           (sphere ? "" : " (inverted, degenerate or misnumbered)"));
    }
    c.gid.push_back(static_cast<int>(firstIndex + k));
    c.x.insert(c.x.end(), g.centroid.begin(), g.centroid.end());
    c.volume.push_back(planar ? g.measure * spec.thickness : g.measure);
    c.block.push_back(e.block[k]);
  }
  return c;
}

void addElementNodeSet(PointCloud& c, const std::string& name, const MeshElements& e, const MeshNodes& n,
                       const std::vector<char>& marked) {
  std::vector<int>& members = c.generatedNodeSets[name];
  for (int k = 0; k < e.size(); ++k)
    for (int m = e.offset[k]; m < e.offset[k + 1]; ++m)
      if (marked[n.find(e.nodes[m])]) {
        members.push_back(c.gid[k]);
        break;
      }
}

}  // namespace pf
