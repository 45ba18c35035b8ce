#include "OutputFields.hpp"

#include <algorithm>

namespace pf {

const std::vector<std::string>& coreVectorFields() {
  static const std::vector<std::string> v = {"Displacement", "Velocity", "Force_Density", "Force",
                                             "Model_Coordinates", "Coordinates", "Acceleration", "External_Force_Density",
                                             "Contact_Force_Density"};
  return v;
}

const std::vector<std::string>& coreScalarFields() {
  static const std::vector<std::string> v = {"Weighted_Volume", "Element_Id", "Proc_Num", "Number_Of_Neighbors",
                                             "Volume", "Horizon", "Damage", "Radius", "Kinetic_Energy"};
  return v;
}

const std::vector<std::string>& fieldScalarOutputs() {
  static const std::vector<std::string> v = {"Temperature", "Temperature_Change", "Flux_Divergence"};
  return v;
}

const std::vector<std::string>& globalFields() {
  static const std::vector<std::string> v = {"Global_Kinetic_Energy", "Global_Strain_Energy", "Global_Dissipated_Energy",
                                             "Global_Wall_Energy_Loss", "Global_Contact_Energy", "Global_Heat",
                                             "Nonlinear_Solver_Iterations"};
  return v;
}

namespace {
bool listed(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}
}  // namespace

bool isCoreVectorField(const std::string& name) { return listed(coreVectorFields(), name); }
bool isCoreScalarField(const std::string& name) { return listed(coreScalarFields(), name); }
bool isGlobalField(const std::string& name) { return listed(globalFields(), name); }

const std::vector<std::string>& tensorFields() {
  static const std::vector<std::string> v = {"Deformation_Gradient", "Shape_Tensor_Inverse", "Left_Stretch_Tensor",
                                             "Rotation_Tensor", "Unrotated_Rate_Of_Deformation", "Cauchy_Stress",
                                             "Unrotated_Cauchy_Stress", "Velocity_Gradient"};
  return v;
}

bool isTensorField(const std::string& name) { return listed(tensorFields(), name); }

const std::vector<std::string>& materialVectorFields() {
  static const std::vector<std::string> v = {"Hourglass_Force_Density"};
  return v;
}

bool isMaterialVectorField(const std::string& name) { return listed(materialVectorFields(), name); }

bool isKinematicTensor(const std::string& name) {
  return name == "Deformation_Gradient" || name == "Shape_Tensor_Inverse";
}

const std::vector<std::string>& tensorComponentSuffixes() {
  static const std::vector<std::string> v = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
  return v;
}

std::string transposedComponentName(const std::string& name) {
  const std::size_t n = name.size();
  auto axis = [](char c) { return c == 'X' || c == 'Y' || c == 'Z'; };
  if (n < 2 || !axis(name[n - 2]) || !axis(name[n - 1])) return name;
  std::string t = name;
  std::swap(t[n - 2], t[n - 1]);
  return t;
}

const char* globalSourceField(const std::string& global) {
  if (global == "Global_Strain_Energy") return "Stored_Elastic_Energy";
  if (global == "Global_Dissipated_Energy") return "Dissipated_Energy";
  if (global == "Global_Wall_Energy_Loss") return "Rigid_Wall_Energy_Loss";
  return nullptr;
}

}  // namespace pf
