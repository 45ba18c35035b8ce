#include "ElasticCorrespondenceMaterial.hpp"

namespace pf {

ElasticCorrespondenceMaterial::ElasticCorrespondenceMaterial(const MaterialInput& in)
    : CorrespondenceMaterial(in, "Elastic Correspondence") {}

MaterialEntry ElasticCorrespondenceMaterial::entry() {
  MaterialEntry e{"Elastic Correspondence",
          "hypoelastic correspondence (non-ordinary state-based) solid with hourglass control (Peridigm; Foster et "
          "al. 2010 kinematics)",
          commonParameters(RateRule::EndOfStep),
          [](const MaterialInput& in) { return std::unique_ptr<Material>(new ElasticCorrespondenceMaterial(in)); },
          commonOutputs()};
  e.createOperators = [](const MaterialInput& in) { return heatTerms(in, "Elastic Correspondence"); };
  return e;
}

void ElasticCorrespondenceMaterial::updateStress(const FamilyView&, StateStore&, const std::vector<Mat3>& tauN,
                                                 const std::vector<Mat3>& de, const std::vector<double>&,
                                                 std::vector<Mat3>& tau) const {
  for (std::size_t k = 0; k < tau.size(); ++k) tau[k] = tauN[k] + elasticIncrement(de[k]);
}

}  // namespace pf
