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

// Throws InputError naming the material and file unless exactly two moduli are given and admissible.
ElasticModuli elasticModuliFrom(const MaterialInput& in);

// Dimension from the "Plane Stress"/"Plane Strain" flags; thickness required (and > 0) when planar.
Dimension dimensionFrom(const MaterialInput& in, double* thickness);

}  // namespace pf
