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
    // Peridigm's parabolicDecay(): flat to half the horizon, then -4s^2 + 4s (continuous at s = 0.5,
    // zero at s = 1).
    case Influence::ParabolicDecay: return s < 0.5 ? 1.0 : -4.0 * s * s + 4.0 * s;
    // Peridigm's gaussian(): exp(-r^2 / delta^2), no width factor.
    case Influence::Gaussian: return std::exp(-s * s);
  }
  return 1.0;
}

}  // namespace pf
