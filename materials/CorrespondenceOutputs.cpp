// CorrespondenceMaterial's optional outputs (Peridigm's Unrotated_Rate_Of_Deformation, Cauchy_Stress and
// Hourglass_Force_Density of its correspondence models, src/materials/Peridigm_CorrespondenceMaterial.cpp): state
// fields filled only when an output asks for them, never read by the update.
#include <cmath>
#include <limits>

#include "CorrespondenceFields.hpp"
#include "CorrespondenceMaterial.hpp"

namespace pf {

std::vector<StateSpec> CorrespondenceMaterial::outputStateSpecs() const {
  std::vector<StateSpec> s;
  addTensorSpecs(s, "Cauchy_Stress", true, true, false, false);  // rewritten by every evaluation that wants it
  // History, so that an evaluation without time passing (the output pass after a quasi-static step's commit)
  // reports the rate of the step that led to the state instead of 0/0.
  addTensorSpecs(s, "Unrotated_Rate_Of_Deformation", true, true, false);
  // The time of the node's last commit (the step's dt: the rate output, Peridigm's velocity-state increment); NaN:
  // never committed, the step then starts at FamilyView::startTime.
  s.push_back({"Correspondence_Time", Location::Node, true, false, std::numeric_limits<double>::quiet_NaN()});
  for (const char* c : {"X", "Y", "Z"}) s.push_back({std::string("Hourglass_Force_Density") + c, Location::Node, false, true});
  return s;
}

void CorrespondenceMaterial::enableTensorOutput(const std::string& name) const {
  auto is = [&](const char* base) { return name.rfind(base, 0) == 0; };
  if (is("Cauchy_Stress")) cauchyWanted_ = true;
  if (is("Unrotated_Rate_Of_Deformation")) rateWanted_ = true;
  if (is("Hourglass_Force_Density")) hourglassWanted_ = true;
}

// Peridigm's field is the unrotated rate of deformation d = R^T D R of the step (correspondence.cxx,
// computeUnrotatedRateOfDeformationAndRotationTensor): the kinematics' increment d dt over dt, the time since the
// node's last commit (stepLengths), at the step's end or its midpoint as the model's 'Rate Of Deformation' says.
void CorrespondenceMaterial::writeRateOfDeformation(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& de,
                                                    const std::vector<double>& dt) const {
  if (!rateWanted_) return;
  TensorField rate(state, "Unrotated_Rate_Of_Deformation", true);
  for (std::size_t k = 0; k < de.size(); ++k) {
    const int i = fam.begin + static_cast<int>(k);
    rate.set(i, dt[k] > 0.0 ? (1.0 / dt[k]) * de[k] : rate.committedAt(i));
  }
}

void CorrespondenceMaterial::writeCauchyStress(const FamilyView& fam, StateStore& state, const std::vector<Mat3>& R,
                                               const std::vector<Mat3>& tau) const {
  if (!cauchyWanted_) return;
  TensorField sigma(state, "Cauchy_Stress", true);
  for (std::size_t k = 0; k < tau.size(); ++k) sigma.set(fam.begin + static_cast<int>(k), mul(R[k], mulNT(tau[k], R[k])));
}

void CorrespondenceMaterial::hourglassFields(StateStore& state, double* out[3]) const {
  for (int a = 0; a < 3; ++a)
    out[a] = hourglassWanted_ ? state.trial(std::string("Hourglass_Force_Density") + "XYZ"[a]) : nullptr;
}

}  // namespace pf
