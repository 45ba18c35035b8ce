#pragma once
// The output fields the core itself provides, whatever the materials: nodal vectors, nodal scalars and
// whole-body (Exodus global) values. Material fields come from each MaterialEntry's `outputs`.
#include <string>
#include <vector>

namespace pf {

const std::vector<std::string>& coreVectorFields();  // 3 components per node: "Displacement", ...
const std::vector<std::string>& coreScalarFields();  // one value per node: "Volume", "Horizon", ...
const std::vector<std::string>& globalFields();      // one value per step: "Global_Kinetic_Energy"

}  // namespace pf
