#pragma once
// The rigid-body motions of a set of points, as the near-null space a smoothed-aggregation preconditioner needs
// for elasticity: three translations and three infinitesimal rotations about a centre (about z alone for a planar
// body). Plain arrays, 3 dofs per point, laid out as the Newton vectors (dof 3 i + component).
#include <vector>

namespace pf {

class Communicator;

struct RigidBodyModes {
  int count = 0;               // 6, or 4 when planar
  std::vector<double> values;  // mode k at dof r: values[k * 3 * points + r]
};

// Modes of `points` points at x (3 per point): translations e_x, e_y, e_z, then rotations about z, x and y
// through `centre`; planar: the rotation about z only.
RigidBodyModes rigidBodyModes(const double* x, int points, const double centre[3], bool planar);

// The same for the owned points of every rank together: the centre is their mean and the body is planar when
// they all share one z. Collective.
RigidBodyModes rigidBodyModes(const std::vector<double>& x, int owned, const Communicator& comm);

}  // namespace pf
