// The list of constitutive models by name ("Material Model" in the input); the types are in
// core/MaterialEntry.hpp. Adding a model = one file pair in materials/ plus one line here.
#include "core/MaterialEntry.hpp"

#include "DiffusionMaterial.hpp"
#include "DruckerPragerCorrespondenceMaterial.hpp"
#include "BondAssociatedCorrespondenceMaterial.hpp"
#include "ElasticBondBasedMaterial.hpp"
#include "ElasticCorrespondenceMaterial.hpp"
#include "ElasticHypoelasticCorrespondenceMaterial.hpp"
#include "ElasticMaterial.hpp"
#include "ElasticPlasticCorrespondenceMaterial.hpp"
#include "ElasticPlasticMaterial.hpp"
#include "HardeningPlasticity.hpp"
#include "LinearLpsMaterial.hpp"
#include "MicroelasticMaterial.hpp"
#include "PalsMaterial.hpp"
#include "ViscoplasticCorrespondenceMaterial.hpp"

namespace pf {

const std::vector<MaterialEntry>& materialRegistry() {
  static const std::vector<MaterialEntry> entries = {
      ElasticMaterial::entry(),
      ElasticMaterial::partialVolumeEntry(),
      LinearLpsMaterial::entry(),
      PalsMaterial::entry(),
      ElasticPlasticMaterial::entry(),
      HardeningPlasticity::entry(),
      MicroelasticMaterial::entry(),
      ElasticBondBasedMaterial::entry(),
      ElasticCorrespondenceMaterial::entry(),
      ElasticPlasticCorrespondenceMaterial::entry(),
      ElasticPlasticCorrespondenceMaterial::hardeningEntry(),
      ElasticPlasticCorrespondenceMaterial::needlemanEntry(),
      ViscoplasticCorrespondenceMaterial::entry(),
      DruckerPragerCorrespondenceMaterial::entry(),
      BondAssociatedCorrespondenceMaterial::elasticEntry(),
      BondAssociatedCorrespondenceMaterial::perfectPlasticEntry(),
      BondAssociatedCorrespondenceMaterial::hardeningEntry(),
      BondAssociatedCorrespondenceMaterial::viscoplasticEntry(),
      BondAssociatedCorrespondenceMaterial::druckerPragerEntry(),
      ElasticHypoelasticCorrespondenceMaterial::entry(),
      DiffusionMaterial::entry(),
  };
  return entries;
}

}  // namespace pf
