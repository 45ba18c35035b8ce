#include "AdaptiveLoadStepping.hpp"

#include <cmath>

#include "core/InputError.hpp"

namespace pf {
namespace {

using Kind = ParamTree::Entry::Kind;

const ParamTree::Entry* typed(const ParamTree& list, const std::string& name, Kind kind, const std::string& where,
                              const char* what) {
  const ParamTree::Entry* e = list.find(name);
  if (e && e->kind != kind) throw InputError(where + ": '" + name + "' must be " + what);
  return e;
}

int count(const ParamTree& list, const std::string& name, const std::string& where, int least, bool required) {
  const ParamTree::Entry* e = typed(list, name, Kind::Int, where, "an int");
  if (!e) {
    if (required) throw InputError(where + ": '" + name + "' is required");
    return least;
  }
  if (e->integer < least)
    throw InputError(where + ": '" + name + "' = " + std::to_string(e->integer) + " must be at least " +
                     std::to_string(least));
  return e->integer;
}

bool flag(const ParamTree& list, const std::string& name, const std::string& where) {
  const ParamTree::Entry* e = typed(list, name, Kind::Bool, where, "a bool");
  return e && e->flag;
}

double positive(const ParamTree& list, const std::string& name, const std::string& where) {
  const ParamTree::Entry* e = typed(list, name, Kind::Double, where, "a double");
  if (!e) return 0.0;
  if (!(e->number > 0.0)) throw InputError(where + ": '" + name + "' must be positive");
  return e->number;
}

void onlyKnown(const ParamTree& list, const std::vector<std::string>& known, const std::string& where) {
  for (const ParamTree::Entry& e : list.entries) {
    bool ok = false;
    for (const std::string& k : known) ok = ok || e.name == k;
    if (!ok) throw InputError(where + ": unknown parameter '" + e.name + "'");
  }
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

AdaptiveLoadStepping parseAdaptiveLoadStepping(const ParamTree& list, const std::string& where) {
  const std::string at = where + "/Adaptive Load-Stepping";
  const std::string inOne = "Maximum load step reductions in one step", total = "Maximum total load step reductions";
  onlyKnown(list, {inOne, total, "Reduce all remaining load steps", "Adaptive output frequency", "Switch to Verlet"}, at);
  AdaptiveLoadStepping a;
  a.on = true;
  a.maxReductionsInStep = count(list, inOne, at, 0, true);
  a.maxTotalReductions = count(list, total, at, 0, true);
  a.reduceRemaining = flag(list, "Reduce all remaining load steps", at);
  a.adaptiveOutput = flag(list, "Adaptive output frequency", at);
  const ParamTree::Entry* sw = typed(list, "Switch to Verlet", Kind::List, at, "a list");
  if (sw) {
    const std::string vat = at + "/Switch to Verlet";
    onlyKnown(*sw->list, {"Safety Factor", "Fixed dt", "Output Frequency"}, vat);
    a.switchToVerlet = true;
    a.verlet.fixedDt = positive(*sw->list, "Fixed dt", vat);
    a.verlet.safetyFactor = positive(*sw->list, "Safety Factor", vat);
    if (a.verlet.fixedDt <= 0.0 && a.verlet.safetyFactor <= 0.0)
      throw InputError(vat + ": give 'Fixed dt' or 'Safety Factor' (the explicit run's time step)");
    a.verlet.peridigmEstimate = true;  // Peridigm's critical time step, as its Verlet
    a.verlet.where = vat;
    a.verletOutputFrequency = count(*sw->list, "Output Frequency", vat, 1, false);
    if (!sw->list->find("Output Frequency")) a.verletOutputFrequency = 0;
  }
  return a;
}

}  // namespace pf
