#pragma once
// Ghosts that follow the deformation (contact): the points of other ranks that lie near this rank's points in the
// current configuration, chosen again at every rebuild, and their values between rebuilds by an import from their
// owners. Boxes are exchanged, then the points inside them: no rank sees the whole cloud.
#include <memory>
#include <vector>

#include "discretization/Discretization.hpp"
#include "parallel/DistributedLayout.hpp"

namespace pf {

class MovingGhosts {
 public:
  explicit MovingGhosts(const DistributedLayout& layout) : layout_(layout) {}
  ~MovingGhosts();
  // Collective. candidates: this rank's owned points that take part, at their current positions (x), with their
  // gids, volumes and blocks. The ghosts become every other rank's candidates within pad of this rank's box.
  void rebuild(const PointCloud& candidates, double pad);
  // The ghosts, ascending by gid; x: their positions at the rebuild.
  const PointCloud& ghosts() const { return ghosts_; }
  // Collective: ncomp values per ghost from the owners' values (ncomp per owned point of the layout, all of them).
  void update(const double* owned, double* ghostValues, int ncomp) const;

 private:
  const DistributedLayout& layout_;
  PointCloud ghosts_;
  std::unique_ptr<const GhostTransfers> transfers_;
  mutable std::vector<double> overlap_;
};

}  // namespace pf
