#pragma once
// Kinematic setting of a model: full 3D, or a 2D slab of given thickness in plane stress or plane strain.
// 2D models keep z = 0 for every point and carry the thickness in the nodal volumes.
#include <string>

namespace pf {

enum class Dimension { ThreeD, PlaneStress, PlaneStrain };

inline bool isPlanar(Dimension d) { return d != Dimension::ThreeD; }

inline const char* toString(Dimension d) {
  switch (d) {
    case Dimension::ThreeD: return "3D";
    case Dimension::PlaneStress: return "Plane Stress";
    case Dimension::PlaneStrain: return "Plane Strain";
  }
  return "?";
}

}  // namespace pf
