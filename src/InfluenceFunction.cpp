#include "InfluenceFunction.hpp"

#include <cmath>

#include "InputError.hpp"

namespace pf {

Influence influenceFromName(const std::string& name, const std::string& inputFile) {
  if (name == "One") return Influence::One;
  if (name == "Parabolic Decay") return Influence::ParabolicDecay;
  if (name == "Gaussian") return Influence::Gaussian;
  throw InputError(inputFile + ": 'Influence Function' = '" + name +
                   "' is not one of 'One', 'Parabolic Decay', 'Gaussian'");
}

double influenceValue(Influence f, double r, double horizon) {
  const double s = r / horizon;
  switch (f) {
    case Influence::One: return 1.0;
    case Influence::ParabolicDecay: return 1.0 - s * s;
    case Influence::Gaussian: return std::exp(-s * s / (0.2 * 0.2)) ;
  }
  return 1.0;
}

}  // namespace pf
