#pragma once
// The output fields the core itself provides, whatever the materials: nodal vectors, nodal scalars and
// whole-body (Exodus global) values. Material fields come from each MaterialEntry's `outputs`.
#include <string>
#include <vector>

namespace pf {

const std::vector<std::string>& coreVectorFields();  // 3 components per node: "Displacement", ...
const std::vector<std::string>& coreScalarFields();  // one value per node: "Volume", "Horizon", ...
// One value per node of a field beside the displacement (model/FieldSet.hpp), written as Exodus nodal variables:
// "Temperature", "Temperature_Change", ...; only when the run holds that field.
const std::vector<std::string>& fieldScalarOutputs();
const std::vector<std::string>& globalFields();      // one value per step: "Global_Kinetic_Energy", ...
bool isCoreVectorField(const std::string& name);
bool isCoreScalarField(const std::string& name);
bool isGlobalField(const std::string& name);

// Tensors an Output Variables list names whole ("Deformation_Gradient"): each is written as 9 element variables
// <name>XX, <name>XY, <name>XZ, <name>YX, ..., <name>ZZ (row-major, Peridigm's Exodus names and order).
// Deformation_Gradient and Shape_Tensor_Inverse the model computes for every material at the steps written
// (kinematicTensor); the others are node fields of the materials that compute them, one per component (a
// symmetric tensor stores only XX, YY, ZZ, XY, YZ, XZ: storedComponentName maps YX to XY and so on).
const std::vector<std::string>& tensorFields();
// Vectors of a material's (Hourglass_Force_Density of the correspondence models): nodal variables <name>X/Y/Z like
// the core's vectors, stored as the node fields <name>X, <name>Y, <name>Z.
const std::vector<std::string>& materialVectorFields();
bool isMaterialVectorField(const std::string& name);
bool isTensorField(const std::string& name);
bool isKinematicTensor(const std::string& name);
const std::vector<std::string>& tensorComponentSuffixes();  // "XX", "XY", ..., "ZZ"
// The same component with its two axis letters swapped ("Cauchy_StressYX" -> "Cauchy_StressXY"); the name itself
// when it does not end in two axis letters.
std::string transposedComponentName(const std::string& name);

// The per-node energy (J per node, not a density) a whole-body global sums over the owned nodes, or null for
// Global_Kinetic_Energy (computed from v). The node field is declared by whoever computes it, so the output
// layer never knows which material or boundary condition sits behind a global:
//   Global_Strain_Energy     = sum Stored_Elastic_Energy   (Peridigm's names; every block's material declares it)
//   Global_Dissipated_Energy = sum Dissipated_Energy       (plastic work; every block's material declares it)
//   Global_Wall_Energy_Loss  = sum Rigid_Wall_Energy_Loss  (the model's Rigid Walls: kinetic energy removed)
//   Global_Contact_Energy    = the energy the contact springs store (Model::termEnergy)
//   Global_Heat              = sum rho c (T - T_start) V  (the heat the Temperature field holds beyond its start)
const char* globalSourceField(const std::string& global);

}  // namespace pf
