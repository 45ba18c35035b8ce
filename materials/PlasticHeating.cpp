#include "PlasticHeating.hpp"

namespace pf {

void PlasticHeating::addSource(const FamilyView& fam, const StateStore& state, double dt, double* out) const {
  const double* w = state.trial("Dissipated_Energy");
  const double* wN = state.committed("Dissipated_Energy");
  for (int i = fam.begin; i < fam.end; ++i) out[i] += beta_ * (w[i] - wN[i]) / (fam.volume[i] * dt);
}

}  // namespace pf
