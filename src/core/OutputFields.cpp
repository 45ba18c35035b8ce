#include "OutputFields.hpp"

namespace pf {

const std::vector<std::string>& coreVectorFields() {
  static const std::vector<std::string> v = {"Displacement", "Velocity", "Force_Density", "Force",
                                             "Model_Coordinates", "Coordinates", "Acceleration"};
  return v;
}

const std::vector<std::string>& coreScalarFields() {
  static const std::vector<std::string> v = {"Weighted_Volume", "Element_Id", "Proc_Num", "Number_Of_Neighbors",
                                             "Volume", "Horizon", "Damage"};
  return v;
}

const std::vector<std::string>& globalFields() {
  static const std::vector<std::string> v = {"Global_Kinetic_Energy"};
  return v;
}

}  // namespace pf
