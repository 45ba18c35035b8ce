#pragma once
// Peridigm's influence functions omega(r, delta), s = r/delta: "One"; "Parabolic Decay" (1 for s < 0.5,
// else -4s^2 + 4s); "Gaussian" (exp(-s^2)), as in Peridigm_InfluenceFunction.hpp. Unknown names are an
// InputError.
#include <string>

namespace pf {

enum class Influence { One, ParabolicDecay, Gaussian };

Influence influenceFromName(const std::string& name, const std::string& inputFile);
double influenceValue(Influence f, double r, double horizon);

}  // namespace pf
