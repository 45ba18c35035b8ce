#pragma once
// Frictionless rigid planes for explicit dynamics, enforced kinematically after the Verlet position update:
// a point of the wall's set found behind the plane is put back on it (moved along the normal) and the
// normal component of its half-step velocity, if it points into the wall, becomes zero: perfectly
// inelastic normal contact, tangential motion free. The momentum this adds per step, over dt, is the
// wall's force on the body, reported as its reaction.
#include <array>
#include <string>
#include <vector>

namespace pf {

struct RigidWall {
  std::string name;
  std::array<double, 3> point{};   // a point of the plane
  std::array<double, 3> normal{};  // unit normal, towards the side the points stay on
  std::vector<int> nodes;          // owned-local indices of the points it stops
};

// For every wall and every node i of it with gap g = (x_i + u_i - p) . n < 0: u_i -= g n, and with
// v_n = v_i . n < 0, v_i -= v_n n. x: reference coordinates, mass: rho V per owned node; u, v: 3 per owned
// node (v the half-step velocity). reaction: 3 per wall, this rank's share of sum m dv / dt.
// loss (per owned node, or null; then a is needed): += the energy the contact dissipated in this step,
//   m (v_n^2 / 2 + v_n dt a_n / 2 - g a_n),   a_n = a_i . n, v_n the removed normal velocity (0 if none),
// with a the acceleration of the step's first half kick (3 per owned node). Why this and not just
// m v_n^2 / 2: a point resting on the wall is kicked into it by the body behind it every step (v_n = dt a_n,
// g = dt^2 a_n) and stopped again without moving; the force does no work on it, and the formula gives 0 there.
// For a point arriving freely (a = 0) it gives the inelastic impact's m v_n^2 / 2. It is the step's internal
// work minus its kinetic energy change for a contact point, (f_n + f_n+1)/2 . du - dKE, with a_n+1 taken as
// a_n: exact for a resting point, an O(dt) error once at the step a point comes into contact (docs/output.md,
// "Energy").
void enforceRigidWalls(const std::vector<RigidWall>& walls, const std::vector<double>& x,
                       const std::vector<double>& mass, double dt, double* u, double* v,
                       std::vector<double>& reaction, const double* a = nullptr, double* loss = nullptr);

}  // namespace pf
