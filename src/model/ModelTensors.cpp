// Model::kinematicTensors: Peridigm's compute class Deformation_Gradient (src/compute/
// Peridigm_Compute_Deformation_Gradient.cpp), run by the output layer at the steps it writes.
#include <cstdio>

#include "Model.hpp"
#include "core/InputError.hpp"
#include "core/ShapeTensor.hpp"
#include "parallel/Collective.hpp"

namespace pf {

// Per owned node, from its whole family in the block's view without damage arrays: Peridigm's compute class keeps
// every bond (its bond damage is a placeholder 0), so a cracked family's F still spans the crack, and K never
// turns singular during a run. The weights are the block's influence function and partial volumes, as in
// the correspondence models.
void Model::kinematicTensors(const double* u, double* F, double* Kinv) {
  layout_->importToOverlap(u, uOverlap_.data(), 3);
  for (std::size_t k = 0; k < yOverlap_.size(); ++k) yOverlap_[k] = x_[k] + uOverlap_[k];
  collectively(layout_->comm(), [&] {
    for (const BlockModel& b : blocks_) {
      const FamilyView fam = blockView(b);
      const bool planar = isPlanar(b.material->dimension());
      for (int i = b.begin; i < b.end; ++i) {
        ShapeAndGradient sg;
        if (!tryShapeAndGradient(fam, i, yOverlap_.data(), planar, sg)) {
          char buf[300];
          std::snprintf(buf, sizeof buf,
                        "Deformation_Gradient: the shape tensor of the point at (%.6g, %.6g, %.6g) (%s) is singular: "
                        "its family needs %s; is the horizon too small for the grid?",
                        x_[3 * i], x_[3 * i + 1], x_[3 * i + 2], b.name.c_str(),
                        planar ? "two non-parallel bonds" : "three non-coplanar bonds");
          throw InputError(buf);
        }
        for (int c = 0; c < 9; ++c) F[9 * i + c] = sg.F[c], Kinv[9 * i + c] = sg.Kinv[c];
      }
    }
  });
}

}  // namespace pf
