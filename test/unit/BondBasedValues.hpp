#pragma once
// The input of a bond-based solid (Microelastic, Elastic Bond Based) in a test: density, bulk modulus and the
// planar flags, with the 2D thickness under the model's name ("Thickness"; Peridigm's "Height" for Elastic Bond
// Based).
#include <map>
#include <string>

#include "core/Dimension.hpp"

namespace pftest {

inline std::map<std::string, double> bondBasedValues(pf::Dimension dim, double bulk, double thickness,
                                                     const char* thicknessName = "Thickness") {
  std::map<std::string, double> v = {{"Density", 7800.0}, {"Bulk Modulus", bulk}};
  if (dim == pf::Dimension::PlaneStress) v["Plane Stress"] = 1;
  if (dim == pf::Dimension::PlaneStrain) v["Plane Strain"] = 1;
  if (dim != pf::Dimension::ThreeD) v[thicknessName] = thickness;
  return v;
}

}  // namespace pftest
