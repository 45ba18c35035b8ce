#include "InfluenceFunction.hpp"

#include <cmath>
#include <cstdio>

#include <RTC_FunctionRTC.hh>

#include "InputError.hpp"
#include "RtcFunctions.hpp"
#include "Words.hpp"

namespace pf {

namespace {

// The compiled function's value at (zeta, horizon); a domain error is left for takeRtcDomainError().
double userDefinedValue(const Influence& f, double zeta, double horizon) {
  PG_RuntimeCompiler::Function& fn = *f.function;
  takeRtcDomainError();
  fn.varValueFill(0, zeta);
  fn.varValueFill(1, horizon);
  fn.varValueFill(2, 0.0);
  if (!fn.execute())
    throw InputError(f.context + ": 'Influence Function' = '" + oneLine(f.expression) + "': cannot evaluate: " +
                     oneLine(fn.getErrors()));
  return fn.getValueOfVar("value");
}

}  // namespace

Influence influenceFromName(const std::string& name, const std::string& inputFile) {
  if (name == "One") return Influence::One;
  if (name == "Parabolic Decay") return Influence::ParabolicDecay;
  if (name == "Gaussian") return Influence::Gaussian;
  // Peridigm (InfluenceFunction::setInfluenceFunction): anything else is an expression in zeta and
  // horizon, "value = " prepended unless the text assigns value itself.
  Influence f(Influence::UserDefined);
  f.expression = name;
  f.context = inputFile;
  std::string body = name.find("value") == std::string::npos ? "value = " + name : name;
  const std::size_t last = body.find_last_not_of(" \t\r\n");
  if (last == std::string::npos)
    throw InputError(inputFile + ": 'Influence Function' is empty (give 'One', 'Parabolic Decay', 'Gaussian' or an "
                                 "expression in zeta and horizon)");
  if (body[last] != ';' && body[last] != '}') body += ";";
  installCheckedRtcFunctions();
  f.function = std::make_shared<PG_RuntimeCompiler::Function>(3, "pf_influence");
  for (const char* v : {"zeta", "horizon", "value"}) f.function->addVar("double", v);
  bool compiled = false;
  const std::string escape = compileRtcBody(*f.function, name, body, compiled);
  if (!escape.empty())
    throw InputError(inputFile + "/Influence Function: cannot compile expression '" + oneLine(name) + "': " + escape);
  if (!compiled)
    throw InputError(inputFile + ": 'Influence Function' = '" + oneLine(name) +
                     "' is not 'One', 'Parabolic Decay', 'Gaussian' nor an expression in zeta and horizon: " +
                     oneLine(f.function->getErrors()));
  const std::string folded = takeRtcDomainError();  // a constant call such as sqrt(-1), folded at compile time
  if (!folded.empty()) throw InputError(inputFile + ": 'Influence Function' = '" + oneLine(name) + "': " + folded);
  // A trial run reports run-time errors at input time; its value is not checked ((1, 1) is no bond).
  userDefinedValue(f, 1.0, 1.0);
  return f;
}

double influenceValue(const Influence& f, double r, double horizon) {
  const double s = r / horizon;
  switch (f.kind) {
    case Influence::One: return 1.0;
    // Peridigm's parabolicDecay(): flat to half the horizon, then -4s^2 + 4s (continuous at s = 0.5,
    // zero at s = 1).
    case Influence::ParabolicDecay: return s < 0.5 ? 1.0 : -4.0 * s * s + 4.0 * s;
    // Peridigm's gaussian(): exp(-r^2 / delta^2), no width factor.
    case Influence::Gaussian: return std::exp(-s * s);
    case Influence::UserDefined: {
      const double w = userDefinedValue(f, r, horizon);
      if (std::isfinite(w)) return w;
      const std::string why = takeRtcDomainError();
      char at[120];
      std::snprintf(at, sizeof at, "' is %g at zeta = %g, horizon = %g", w, r, horizon);
      throw InputError(f.context + ": 'Influence Function' = '" + oneLine(f.expression) + at +
                       (why.empty() ? "" : ": " + why));
    }
  }
  return 1.0;
}

}  // namespace pf
