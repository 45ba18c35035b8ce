#include "PeridigmTimeStep.hpp"

#include <algorithm>
#include <cmath>

#include "model/Model.hpp"

namespace pf {

double peridigmCriticalTimeStep(const Model& model) {
  const BondFamily& fam = model.layout().family();
  double smallest = 1.0e50;  // Peridigm's "no bond" value
  for (const BlockModel& b : model.blocks()) {
    if (!(b.bulkModulus > 0.0)) continue;
    for (int i = b.begin; i < b.end; ++i) {
      const double h = model.horizonOf(i, b);  // Peridigm_CriticalTimeStep.cpp: each point's own horizon
      const double c = 18.0 * b.bulkModulus / (M_PI * h * h * h * h);
      double denominator = 0.0;
      for (int k = fam.offsets[i]; k < fam.offsets[i + 1]; ++k)
        denominator += model.volume()[fam.neighbors[k]] * c / fam.refLength[k];
      if (fam.offsets[i + 1] > fam.offsets[i]) smallest = std::min(smallest, std::sqrt(2.0 * model.density()[i] / denominator));
    }
  }
  return -model.max(-smallest);
}

}  // namespace pf
