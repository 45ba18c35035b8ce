#pragma once
// Parameters every OSB solid accepts: density, elastic moduli (any two), planar options, and the Peridigm
// options: "Apply Shear Correction Factor" as each Peridigm model treats it, and ones Periforge ignores.
#include <memory>
#include <string>
#include <vector>

#include "core/Dimension.hpp"
#include "core/Parameters.hpp"

namespace pf {

struct ParameterValues;
using MaterialInput = ParameterValues;

// How a model treats "Apply Shear Correction Factor", as its Peridigm namesake does.
enum class ShearCorrection {
  IgnoredAsPeridigm,  // Peridigm's Elastic / Elastic Plastic have none: default false, true ignored + warning
  Peridigm3D,         // Peridigm's Elastic Plastic Hardening: applied, default true in 3D (false in 2D)
};

std::vector<ParameterSpec> elasticSolidParameters(ShearCorrection scf = ShearCorrection::IgnoredAsPeridigm);

// "Surface Correction" of the OSB solids (Elastic, Elastic Plastic, Elastic Plastic Hardening): `None` (default,
// Peridigm's model) or `Position Aware` (the model builder rewrites the block's influence function,
// src/model/PositionAwareInfluence.hpp, which the builder calls; the material's kernels are unchanged).
ParameterSpec osbSurfaceCorrection();

// Peridigm3D: whether the factor is applied (given value, else 3D); InputError for true in 2D.
bool shearCorrectionOf(const MaterialInput& in, Dimension dim);
// IgnoredAsPeridigm: warns when the deck asks for it; always false.
bool ignoredShearCorrection(const MaterialInput& in, const std::string& model);

// The parameters plus Peridigm's "Thermal Expansion Coefficient" (for a model that honours it) and the conduction
// parameters "Thermal Conductivity", "Specific Heat Capacity" (materials/HeatConduction.hpp); plasticHeating: also
// "Taylor-Quinney Coefficient" (heatParameters).
std::vector<ParameterSpec> withThermalExpansion(std::vector<ParameterSpec> params, bool plasticHeating = false);
// "Thermal Conductivity", "Specific Heat Capacity" and, for a model that integrates its plastic work
// (Dissipated_Energy), "Taylor-Quinney Coefficient" (materials/PlasticHeating.hpp).
std::vector<ParameterSpec> heatParameters(bool plasticHeating);
class FieldOperator;
// The heat conduction of a solid with "Thermal Conductivity" (family normalisation), or null without it.
std::unique_ptr<FieldOperator> conductionOf(const MaterialInput& in, Dimension dim, double thickness);
// Its terms on Temperature: conduction (with "Thermal Conductivity") and plastic heating (with "Taylor-Quinney
// Coefficient", which needs "Specific Heat Capacity"; InputError otherwise).
std::vector<std::unique_ptr<FieldOperator>> heatTermsOf(const MaterialInput& in, Dimension dim, double thickness);
struct ElasticModuli;
// The coefficient a of the thermal extension a dT |xi| (materials/OsbThermalKernels.hpp) or of the thermal strain
// a dT (correspondence): alpha in 3D and plane stress, (1 + nu) alpha in plane strain; 0 when not given.
double thermalExpansionOf(const MaterialInput& in, Dimension dim, const ElasticModuli& moduli);

}  // namespace pf
