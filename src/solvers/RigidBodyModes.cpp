#include "RigidBodyModes.hpp"

#include <algorithm>

#include "parallel/Communicator.hpp"

namespace pf {

RigidBodyModes rigidBodyModes(const double* x, int points, const double centre[3], bool planar) {
  RigidBodyModes modes;
  modes.count = planar ? 4 : 6;
  const std::size_t n = 3 * static_cast<std::size_t>(points);
  modes.values.assign(modes.count * n, 0.0);
  for (int k = 0; k < modes.count; ++k) {
    double* mode = &modes.values[k * n];
    for (int i = 0; i < points; ++i) {
      const double r[3] = {x[3 * i] - centre[0], x[3 * i + 1] - centre[1], x[3 * i + 2] - centre[2]};
      double* v = mode + 3 * i;
      switch (k) {
        case 0: case 1: case 2: v[k] = 1.0; break;
        case 3: v[0] = -r[1]; v[1] = r[0]; break;  // about z: e_z x r
        case 4: v[1] = -r[2]; v[2] = r[1]; break;  // about x: e_x x r
        default: v[0] = r[2]; v[2] = -r[0]; break; // about y: e_y x r
      }
    }
  }
  return modes;
}

RigidBodyModes rigidBodyModes(const std::vector<double>& x, int owned, const Communicator& comm) {
  double sums[4] = {0, 0, 0, static_cast<double>(owned)}, total[4];
  double zExtent[2] = {-1e300, -1e300}, zGlobal[2];  // max z and max -z
  for (int i = 0; i < owned; ++i) {
    for (int d = 0; d < 3; ++d) sums[d] += x[3 * i + d];
    zExtent[0] = std::max(zExtent[0], x[3 * i + 2]);
    zExtent[1] = std::max(zExtent[1], -x[3 * i + 2]);
  }
  comm.sum(sums, total, 4);
  comm.max(zExtent, zGlobal, 2);
  double centre[3] = {0, 0, 0};
  if (total[3] > 0)
    for (int d = 0; d < 3; ++d) centre[d] = total[d] / total[3];
  const bool planar = zGlobal[0] + zGlobal[1] == 0.0;  // max z = min z
  return rigidBodyModes(x.data(), owned, centre, planar);
}

}  // namespace pf
