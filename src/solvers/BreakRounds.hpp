#pragma once
// Quasi-static load steps with bond damage (docs/input.md, "Damage Models"): the iterations of a solve never
// break a bond (an iterate's overshoot, or a predictor's jump at a loaded layer, would otherwise break bonds
// that the equilibrium does not stretch, and the separated body is an equilibrium too); the breaks are
// decided from the converged state, then the same step is solved again with them, until a converged state
// breaks no further bond (at most kMaxBreakRounds rounds, else SolverFailure). Without damage: solve() once.
#include <functional>
#include <vector>

#include "model/Model.hpp"

namespace pf {

constexpr int kMaxBreakRounds = 50;

// solve(): one solve of the step from the current u (true: converged; may throw SolverFailure). On true the
// model's trial state is its evaluation at the final u with the final broken set, ready to commit, and the
// model is still in its break rounds: the caller commits and then calls model.endBreakRounds(). On false
// or a throw the rounds are ended here. t: the step's end, for the message.
bool solveWithBreakRounds(Model& model, std::vector<double>& u, const std::function<bool()>& solve, double t);

}  // namespace pf
