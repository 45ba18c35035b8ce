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

// The per-node energy (J per node, not a density) a whole-body global sums over the owned nodes, or null for
// Global_Kinetic_Energy (computed from v). The node field is declared by whoever computes it, so the output
// layer never knows which material or boundary condition sits behind a global:
//   Global_Strain_Energy     = sum Stored_Elastic_Energy   (Peridigm's names; every block's material declares it)
//   Global_Dissipated_Energy = sum Dissipated_Energy       (plastic work; every block's material declares it)
//   Global_Wall_Energy_Loss  = sum Rigid_Wall_Energy_Loss  (the model's Rigid Walls: kinetic energy removed)
const char* globalSourceField(const std::string& global);

}  // namespace pf
