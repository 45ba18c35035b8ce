#pragma once
// Peridigm's adaptive load stepping for its QuasiStatic solver (the `Adaptive Load-Stepping` sub-list, Peridigm.cpp):
// a load step that does not converge is halved, until a step has been halved `Maximum load step reductions in one
// step` times or the run `Maximum total load step reductions` times; then the run stops, or, with a `Switch to Verlet`
// list, goes on explicitly from the last converged state to the Final Time. Parsed once here into a typed spec.
#include <string>
#include <vector>

#include "VerletSolver.hpp"
#include "core/ParamTree.hpp"
#include "core/Parameters.hpp"

namespace pf {

struct AdaptiveLoadStepping {
  bool on = false;
  int maxReductionsInStep = 0;
  int maxTotalReductions = 0;
  bool reduceRemaining = false;  // a halved step also halves every later one (equal steps to the Final Time)
  bool adaptiveOutput = false;   // each reduction doubles the Output lists' frequency
  bool switchToVerlet = false;
  VerletOptions verlet;          // the explicit run's time step (Fixed dt, or Safety Factor x Peridigm's estimate)
  int verletOutputFrequency = 0; // > 0: replaces the Output lists' frequency in the explicit run
};

// The sub-list `Adaptive Load-Stepping` of a QuasiStatic list (solverList: that list's values, for the file and the
// path); InputError naming the parameter for an unknown name, a wrong type, a missing one or a value out of range.
AdaptiveLoadStepping parseAdaptiveLoadStepping(const ParamTree& list, const ParameterValues& solverList);

// The load times after the step [tA, tB] (tB one of times) is halved: tA + (tB - tA) / 2 goes in before tB, or with
// reduceRemaining every step from tA on becomes equal and at most that long, ending at times.back(). Returns the
// new step length.
double halveStep(std::vector<double>& times, double tA, double tB, bool reduceRemaining);

}  // namespace pf
