#pragma once
// Peridigm's influence functions omega(r, delta): "One", "Parabolic Decay" (1 - (r/delta)^2) and
// "Gaussian" (exp(-(r/delta)^2 / ... )) as Peridigm defines them. Unknown names are an InputError.
#include <string>

namespace pf {

enum class Influence { One, ParabolicDecay, Gaussian };

Influence influenceFromName(const std::string& name, const std::string& inputFile);
double influenceValue(Influence f, double r, double horizon);

}  // namespace pf
