// Model's share of the loading-balance correction (Model.hpp, solvers/YieldRounds.hpp): the admitted plastic
// set handed to the materials and the count of the points it admits.
#include "Model.hpp"

namespace pf {

std::string Model::yieldRoundsRefusal() const {
  for (const BlockModel& b : blocks_)
    if (!b.material->supportsYieldRounds()) return "block '" + b.name + "': material '" + b.materialName + "'";
  return "";
}

void Model::beginYieldRounds(double onSurfaceTol) {
  admitted_.assign(numOwned(), 0);
  yieldRounds_ = true;
  if (onSurfaceTol < 0.0 || !state_.has("Yield_Function")) return;
  const double* f = state_.committed("Yield_Function");  // a history field: checkpointed, so restarts agree
  for (int i = 0; i < numOwned(); ++i) admitted_[i] = f[i] >= -onSurfaceTol ? 1 : 0;
}

double Model::admitYielding(double tol) {
  if (!state_.has("Yield_Function")) return 0.0;
  const double* f = state_.trial("Yield_Function");
  double added = 0.0;
  for (int i = 0; i < numOwned(); ++i)
    if (!admitted_[i] && f[i] > tol) admitted_[i] = 1, added += 1.0;
  return sum(added);
}

}  // namespace pf
