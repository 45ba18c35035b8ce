#include "RigidWall.hpp"

namespace pf {

void enforceRigidWalls(const std::vector<RigidWall>& walls, const std::vector<double>& x,
                       const std::vector<double>& mass, double dt, double* u, double* v,
                       std::vector<double>& reaction, const double* a, double* loss) {
  reaction.assign(3 * walls.size(), 0.0);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const RigidWall& wall = walls[w];
    const double* n = wall.normal.data();
    double impulse = 0.0;  // sum m dv . n over the wall's points this step (>= 0)
    for (int i : wall.nodes) {
      double gap = 0.0, vn = 0.0;
      for (int c = 0; c < 3; ++c) {
        gap += (x[3 * i + c] + u[3 * i + c] - wall.point[c]) * n[c];
        vn += v[3 * i + c] * n[c];
      }
      if (!(gap < 0.0)) continue;
      // Putting the point back is a projection of its position, not a change of momentum; the momentum
      // the wall takes is the velocity projection's, so the reaction is exactly sum m dv / dt.
      for (int c = 0; c < 3; ++c) u[3 * i + c] -= gap * n[c];
      const double removed = vn < 0.0 ? vn : 0.0;
      if (loss) {
        const double an = a[3 * i] * n[0] + a[3 * i + 1] * n[1] + a[3 * i + 2] * n[2];
        loss[i] += mass[i] * (0.5 * removed * removed + 0.5 * removed * dt * an - gap * an);
      }
      if (!(vn < 0.0)) continue;
      for (int c = 0; c < 3; ++c) v[3 * i + c] -= vn * n[c];
      impulse -= mass[i] * vn;
    }
    for (int c = 0; c < 3; ++c) reaction[3 * w + c] = impulse / dt * n[c];
  }
}

}  // namespace pf
