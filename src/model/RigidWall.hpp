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
void enforceRigidWalls(const std::vector<RigidWall>& walls, const std::vector<double>& x,
                       const std::vector<double>& mass, double dt, double* u, double* v,
                       std::vector<double>& reaction);

}  // namespace pf
