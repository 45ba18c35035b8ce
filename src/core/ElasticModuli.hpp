#pragma once
// Isotropic elastic constants from any two of bulk, shear, Young's modulus and Poisson's ratio, as
// Peridigm accepts them; plus the planar setting (Plane Stress / Plane Strain, Thickness) of a material.
#include "core/Dimension.hpp"

namespace pf {

struct ParameterValues;
using MaterialInput = ParameterValues;

struct ElasticModuli {
  double bulk = 0, shear = 0, young = 0, poisson = 0;
};

// Throws InputError naming the material and file unless exactly two moduli are given and they make a
// positive bulk and shear modulus (each one's own range is its ParameterSpec's, checked by the input).
ElasticModuli elasticModuliFrom(const MaterialInput& in);

// Dimension from the "Plane Stress"/"Plane Strain" flags (not both); the thickness (parameter `thicknessName`:
// "Thickness", or "Height" for Peridigm's Elastic Bond Based) required when planar and refused in 3D (its
// range, > 0, is its spec's).
Dimension dimensionFrom(const MaterialInput& in, double* thickness, const char* thicknessName = "Thickness");

}  // namespace pf
