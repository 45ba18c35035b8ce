#include "AdaptiveLoadStepping.hpp"

#include <cmath>

#include "core/InputError.hpp"

namespace pf {
namespace {

using S = ParameterSpec;

const std::vector<ParameterSpec>& adaptiveSpecs() {
  static const std::vector<ParameterSpec> specs = {
      S::integer("Maximum load step reductions in one step").need().nonNegative(),
      S::integer("Maximum total load step reductions").need().nonNegative(),
      S::flag("Reduce all remaining load steps").byDefault("false"),
      S::flag("Adaptive output frequency").byDefault("false")};
  return specs;
}

const std::vector<ParameterSpec>& switchSpecs() {
  static const std::vector<ParameterSpec> specs = {S::real("Safety Factor").positive(), S::real("Fixed dt").positive(),
                                                   S::integer("Output Frequency").atLeast(1)};
  return specs;
}

bool ofKind(const ParamTree::Entry& e, ParameterSpec::Kind kind) {
  using K = ParamTree::Entry::Kind;
  switch (kind) {
    case ParameterSpec::Kind::Double: return e.kind == K::Double || e.kind == K::Int;
    case ParameterSpec::Kind::Int: return e.kind == K::Int;
    case ParameterSpec::Kind::Bool: return e.kind == K::Bool;
    default: return e.kind == K::String;
  }
}

// The list's values checked against specs as a deck's list is (applySpecs: unknown names, required ones, ranges,
// defaults), after its own type check; `sublist` (or none) is the one sub-list it may hold, left to the caller.
ParameterValues valuesOf(const ParamTree& list, const std::vector<ParameterSpec>& specs, const std::string& file,
                         const std::string& path, const std::string& sublist) {
  ParameterValues in;
  in.inputFile = file;
  in.path = path;
  for (const ParamTree::Entry& e : list.entries) {
    if (e.kind == ParamTree::Entry::Kind::List) {
      if (e.name != sublist) throw InputError(in.where() + ": unknown sub-list '" + e.name + "'");
      continue;
    }
    const ParameterSpec* spec = nullptr;
    for (const ParameterSpec& s : specs) spec = s.name == e.name ? &s : spec;
    if (spec && !ofKind(e, spec->kind))
      throw InputError(in.where() + ": '" + e.name + "' must be of type " + kindName(spec->kind));
    if (e.kind == ParamTree::Entry::Kind::String)
      in.strings[e.name] = e.text;
    else
      in.values[e.name] = e.kind == ParamTree::Entry::Kind::Double ? e.number
                          : e.kind == ParamTree::Entry::Kind::Int  ? e.integer
                                                                   : (e.flag ? 1.0 : 0.0);
  }
  applySpecs(specs, in);
  return in;
}

}  // namespace

double halveStep(std::vector<double>& times, double tA, double tB, bool reduceRemaining) {
  const double half = 0.5 * (tB - tA);
  std::size_t k = 1;
  while (k < times.size() && times[k] != tB) ++k;
  if (!reduceRemaining) {
    times.insert(times.begin() + static_cast<long>(k), tA + half);
    return half;
  }
  const double tEnd = times.back();
  // The fewest equal steps no longer than half (a quotient a rounding above an integer is that integer).
  const long n = static_cast<long>(std::ceil((tEnd - tA) / half * (1.0 - 1e-12)));
  times.resize(k);
  for (long j = 1; j < n; ++j) times.push_back(tA + (tEnd - tA) * static_cast<double>(j) / static_cast<double>(n));
  times.push_back(tEnd);
  return (tEnd - tA) / static_cast<double>(n);
}

AdaptiveLoadStepping parseAdaptiveLoadStepping(const ParamTree& list, const ParameterValues& solverList) {
  const std::string path = solverList.path + "/Adaptive Load-Stepping";
  const ParameterValues p = valuesOf(list, adaptiveSpecs(), solverList.inputFile, path, "Switch to Verlet");
  AdaptiveLoadStepping a;
  a.on = true;
  a.maxReductionsInStep = static_cast<int>(p.get("Maximum load step reductions in one step"));
  a.maxTotalReductions = static_cast<int>(p.get("Maximum total load step reductions"));
  a.reduceRemaining = p.flag("Reduce all remaining load steps");
  a.adaptiveOutput = p.flag("Adaptive output frequency");
  if (const ParamTree::Entry* sw = list.find("Switch to Verlet")) {
    const ParameterValues v = valuesOf(*sw->list, switchSpecs(), solverList.inputFile, path + "/Switch to Verlet", "");
    if (!v.has("Fixed dt") && !v.has("Safety Factor"))
      throw InputError(v.where() + ": give 'Fixed dt' or 'Safety Factor' (the explicit run's time step)");
    a.switchToVerlet = true;
    a.verlet.fixedDt = v.get("Fixed dt", 0.0);
    a.verlet.safetyFactor = v.get("Safety Factor", 0.0);
    a.verlet.peridigmEstimate = true;  // Peridigm's critical time step, as its Verlet
    a.verlet.where = v.where();
    a.verletOutputFrequency = static_cast<int>(v.get("Output Frequency", 0.0));
  }
  return a;
}

}  // namespace pf
