#pragma once
// The solvers' guard against non-finite state. A solver passes a norm (or any sum) it already computed
// over its owned values; only when that is non-finite on some rank does the check search the values for
// the first offending node (smallest global id over all ranks). Every rank then throws the same
// SolverFailure, so nothing non-finite reaches the output observer.
#include <string>
#include <vector>

#include "core/Material.hpp"

namespace pf {

class Model;

// Where the check runs, for the message "<solver>: non-finite <what> at step <step> (t = <t>) ...".
struct CheckPoint {
  const char* solver;
  long step;
  double time;
};

// True when localNorm is finite on every rank (collective: every rank must call it).
bool finiteEverywhere(const Model& model, double localNorm);

// Collective. When localNorm is non-finite on some rank, throws InputError naming a boundary condition
// that is not finite at the time, else SolverFailure naming the step, time and the first node (global
// id, coordinates) whose value in x (3 per owned node) is not finite.
void requireFinite(const Model& model, const CheckPoint& at, const char* what, const std::vector<double>& x,
                   double localNorm);

// Collective. When localProbe (a sum over u, v and f) is non-finite on some rank, throws SolverFailure
// naming the first non-finite displacement, else velocity, else force.
void requireFiniteState(const Model& model, const CheckPoint& at, const std::vector<double>& u,
                        const std::vector<double>& v, const std::vector<double>& f, double localProbe);

std::string stepText(const CheckPoint& at);  // " in <solver> step <step> (t = <time>)"

// Runs evaluate() (a force evaluation); a ConstitutiveFailure from it (every rank gets the same one) comes
// back naming where the solver was: "... in <solver> step <step> (t = <time>)".
template <class Evaluate>
void atStep(const CheckPoint& at, Evaluate&& evaluate) {
  try {
    evaluate();
  } catch (const ConstitutiveFailure& e) {
    throw ConstitutiveFailure(std::string(e.what()) + stepText(at));
  }
}
// Sum of the values: finite when every value is (barring overflow near 1e308, itself a failure).
double finiteProbe(const std::vector<double>& x);

}  // namespace pf
