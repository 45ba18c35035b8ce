#include "model/BlockRules.hpp"

#include <cstdio>

#include "core/InputError.hpp"

namespace pf {

// Peridigm's Interface Aware damage breaks a bond past the smaller of its two ends' critical stretches, and never a
// bond whose far end lies in a block without that model (its Critical_Stretch field is 0 there). With every block
// on an Interface Aware model of one value that is exactly the Critical Stretch rule the kernels apply per block;
// the per-bond thresholds of other decks are not implemented, so those are refused rather than run differently.
void requireUniformInterfaceAware(const Deck& deck) {
  const DamageModelSpec* first = nullptr;
  for (const BlockGroupSpec& g : deck.blocks) {
    const DamageModelSpec* d = deck.damageModel(g.damageModel);
    if (d && d->model == "Interface Aware" && !first) first = d;
  }
  if (!first) return;
  for (const BlockGroupSpec& g : deck.blocks) {
    const DamageModelSpec* d = deck.damageModel(g.damageModel);
    if (!d || d->model != "Interface Aware" || d->criticalStretch != first->criticalStretch)
      throw InputError(deck.file + ": Blocks/" + g.name + ": 'Damage Model': with 'Interface Aware' damage ('" +
                       first->name + "') every block needs an Interface Aware model of the same 'Critical Stretch' " +
                       "(per-bond thresholds across blocks are not implemented; docs/input.md, \"Damage\")");
  }
}

// A horizon below the grid spacing reaches no neighbour: every point of the block would have no bond.
void requireHorizonsReachNeighbours(const Deck& deck, const PointCloud& cloud) {
  if (cloud.spacing <= 0) return;  // not a uniform grid: the spacing is unknown
  for (const BlockGroupSpec& g : deck.blocks)
    if (!g.horizonExpression && g.horizon < cloud.spacing) {
      char msg[200];
      std::snprintf(msg, sizeof msg, ": Horizon = %g is smaller than the grid spacing %g: no point would have a bond",
                    g.horizon, cloud.spacing);
      throw InputError(deck.file + ": Blocks/" + g.name + msg);
    }
}

// A two-phase (gather-form) model takes a bond's reaction with the bond's own omega and partial volume, which
// holds where both ends have the same horizon; the correspondence models sum the other points' bonds one-pass
// (CorrespondenceMaterial::computeForce). The NDO band and Maximum Principal Stress damage need the gather form at
// every point, and so do the gather-form models without a one-pass sum (bond-associated correspondence,
// !takesPointHorizon): a block with any of them shares a body only with blocks of its own constant horizon.
void requireEqualHorizonsForGatherForms(const std::map<int, BlockSpec>& blocks, const std::string& inputFile) {
  const BlockSpec* gather = nullptr;
  {
    const BlockSpec* first = nullptr;  // one body takes one layout of per-point rows (bond-associated or not)
    for (const auto& kv : blocks) {
      if (kv.second.material->exchangeWidth(FamilyView{}) == 0) continue;
      if (first && first->material->exchangeLayout() != kv.second.material->exchangeLayout())
        throw InputError(inputFile + ": Blocks/" + kv.second.name + ": its material (" + kv.second.materialName +
                         ") and block " + first->name + "'s (" + first->materialName +
                         ") pass different per-point rows between neighbours; one body takes only one of them");
      if (!first) first = &kv.second;
    }
  }
  for (const auto& kv : blocks)
    if (kv.second.material->exchangeWidth(FamilyView{}) > 0 &&
        (kv.second.ndoBand || kv.second.tensileStrength > 0.0 || !kv.second.material->takesPointHorizon()))
      gather = &kv.second;
  if (!gather) return;
  for (const auto& kv : blocks)
    if (kv.second.horizonExpression || gather->horizonExpression || kv.second.horizon != gather->horizon) {
      const auto text = [](const BlockSpec& b) {
        char v[64];
        std::snprintf(v, sizeof v, "%g", b.horizon);
        return b.horizonExpression ? "'" + b.horizonExpression->text() + "'" : std::string(v);
      };
      throw InputError(inputFile + ": Blocks/" + kv.second.group + ": Horizon = " + text(kv.second) + " differs from " +
                       gather->name + "'s " + text(*gather) + "; its correspondence material (" + gather->materialName +
                       ") with " + (gather->ndoBand                 ? "Surface Correction = NDO Band"
                          : gather->tensileStrength > 0.0 ? "Maximum Principal Stress damage"
                                                          : "its gather form (no one-pass sum for a point's own horizon)") +
                       " sums each bond from both ends and needs one horizon across the body");
    }
}

}  // namespace pf
