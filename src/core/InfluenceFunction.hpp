#pragma once
// Peridigm's influence functions omega(r, delta), s = r/delta: "One"; "Parabolic Decay" (1 for s < 0.5,
// else -4s^2 + 4s); "Gaussian" (exp(-s^2)), as in Peridigm_InfluenceFunction.hpp. Any other string is, as
// in Peridigm, a user-defined function compiled by Pamgen's RTCompiler in the variables zeta (the bond's
// reference length, not scaled) and horizon, e.g. "1.0/zeta"; one that does not compile is an InputError.
#include <memory>
#include <string>

namespace PG_RuntimeCompiler {
class Function;
}

namespace pf {

struct Influence {
  enum Kind { One, ParabolicDecay, Gaussian, UserDefined };
  Kind kind = One;
  std::string expression;                                   // UserDefined only
  std::string context;  // where it was given, for errors, e.g. "input.xml: Discretization"
  std::shared_ptr<PG_RuntimeCompiler::Function> function;  // compiled expression, UserDefined only
  Influence(Kind k = One) : kind(k) {}
  bool operator==(Kind k) const { return kind == k; }
};

Influence influenceFromName(const std::string& name, const std::string& inputFile);
// Not thread-safe for UserDefined (the compiled function keeps its variables as state); it is called
// once per bond at set-up. A UserDefined value that is not finite is an InputError naming zeta, the
// horizon and, for an argument outside a function's domain, the call (e.g. "sqrt(-1) is undefined").
double influenceValue(const Influence& f, double r, double horizon);

}  // namespace pf
