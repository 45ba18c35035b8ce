#pragma once
// The quadratic load-step predictor (NOXQuasiStatic `Predictor` = `Quadratic`): the last three states a solve reached
// and the extrapolation of the free dofs through them to the next load, the load measured along the prescribed dofs.
// Exact for a path quadratic in the load (a large-displacement elastic step, whose linear prediction leaves the path's
// second difference as its residual). A step accepted at its prediction is not recorded: its error, up to the
// tolerance, would enter the next extrapolation with a weight of 3 or more.
#include <vector>

namespace pf {

class Model;

struct CarriedState;

struct SolvedStates {
  std::vector<double> u[3];  // oldest first
  double count = 0;          // how many of u hold states (a double: carried as a checkpoint scalar)
  void record(const std::vector<double>& state);  // the newest; the oldest of three is dropped
  // Registers u and count with a solver's carried state ("Solved State 1..3", "Solved States").
  void carriedBy(CarriedState& own);
};

// u: the newest state with its prescribed dofs already at the next load. Moves u's free dofs to the quadratic through
// the three states and returns true; returns false, u unchanged, when fewer than three are kept or the prescribed
// dofs do not move along one line in one direction through them to the next load (a turn of the load, or a
// non-proportional one). Collective (one reduction).
bool predictQuadratic(const Model& model, const SolvedStates& states, std::vector<double>& u);

}  // namespace pf
