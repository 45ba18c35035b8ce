#pragma once
// What the bond-associated correspondence models (BondAssociatedCorrespondenceMaterial with each of its laws, Elastic
// Hypoelastic Correspondence) share besides their kinematics (BondAssociatedKinematics.hpp) and state
// (BondTensorFields.hpp): the time since a node's last commit, a row's tensor, a point in messages, the common
// parameters, outputs and order check, the preconditioner's pair stiffness. Internal to those materials.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "CorrespondenceFields.hpp"
#include "core/BondFamily.hpp"
#include "core/InputError.hpp"
#include "core/MaterialEntry.hpp"
#include "core/Tensor3.hpp"

namespace pf {

// The time since node i's last commit (Correspondence_Time; FamilyView::startTime before any). timeN: its committed
// array, looked up once per call.
inline double bondAssociatedStepLength(const FamilyView& fam, const double* timeN, int i) {
  return fam.time - (std::isnan(timeN[i]) ? fam.startTime : timeN[i]);
}

// The 3x3 tensor stored at the start of an exchange row.
inline Mat3 rowTensor(const double* row) {
  return Mat3{row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8]};
}

// "(x, y, z)" of point i, for error lines.
inline std::string pointAt(const FamilyView& fam, int i) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", fam.x[3 * i], fam.x[3 * i + 1], fam.x[3 * i + 2]);
  return buf;
}

// Density, two of the four elastic constants and Peridigm's Gradient Order Of Accuracy (only 1 implemented).
inline std::vector<ParameterSpec> bondAssociatedParameters() {
  using P = ParameterSpec;
  return {P::real("Density", "mass density [kg/m^3]").need().positive(),
          P::real("Bulk Modulus", "give exactly two of the four elastic constants").positive(),
          P::real("Shear Modulus").positive(),
          P::real("Young's Modulus").positive(),
          P::real("Poisson's Ratio").above(-1.0).below(0.5),
          P::integer("Gradient Order Of Accuracy", "order of the gradient weights (Peridigm); only 1 is implemented")
              .byDefault("1").atLeast(1)};
}

// Peridigm's higher orders (computeLagrangianGradientWeights with polynomial moments) are not implemented.
inline void requireFirstOrderGradients(const MaterialInput& in) {
  if (in.get("Gradient Order Of Accuracy") != 1.0)
    throw InputError(in.where() + ": 'Gradient Order Of Accuracy' = " +
                     std::to_string(static_cast<long>(in.get("Gradient Order Of Accuracy"))) + ": only 1 is implemented");
}

// The node outputs both models write (addBondAssociatedSpecs), plus a model's own scalars and full tensors.
inline std::vector<std::string> bondAssociatedOutputs(const std::vector<const char*>& extraScalars,
                                                      const std::vector<const char*>& extraFull) {
  std::vector<std::string> outputs;
  for (const char* base : {"Unrotated_Cauchy_Stress", "Cauchy_Stress", "Unrotated_Rate_Of_Deformation"})
    for (const char* c : kSym) outputs.push_back(std::string(base) + c);
  outputs.push_back("Von_Mises_Stress");
  outputs.insert(outputs.end(), extraScalars.begin(), extraScalars.end());
  std::vector<const char*> full = {"Deformation_Gradient", "Rotation_Tensor", "Left_Stretch_Tensor"};
  full.insert(full.end(), extraFull.begin(), extraFull.end());
  for (const char* base : full)
    for (const char* c : kFull) outputs.push_back(std::string(base) + c);
  return outputs;
}

// The bond-based solid with the same bulk modulus, 18 K / (pi delta^4) / |xi|: a preconditioner needs only the scale.
inline void bondAssociatedPairStiffness(const FamilyView& fam, double bulk, double* c) {
  const double d = fam.horizon;
  const double base = 18.0 * bulk / (3.14159265358979323846 * d * d * d * d);
  for (int i = fam.begin; i < fam.end; ++i)
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) c[b] = base / fam.refLength[b];
}

}  // namespace pf
