#pragma once
// Loading-balance correction (Li & Geng, seed 003, Sec. 4.1, Fig. 4, Remark 2) for one quasi-static load step.
// Balance module: relax with the admitted plastic set frozen (a point outside it responds elastically even past
// its yield surface). Correction module: admit every point outside the set whose yield function exceeds a
// tolerance (ADR 'Loading Balance Tolerance', default kYieldTolerance). The two alternate until a relaxed state
// admits none; the caller then commits. The set starts empty each step (the paper: "at the start of a new
// loading step, all particles are assumed to behave as linear elastic materials"); a point once admitted stays
// admitted for the step (its return map gives the elastic state anyway if it unloads), so the rounds end after
// at most one more than the points that yield. Option (ADR 'Loading Balance Start' = "Yield Surface"): start
// with the points on their yield surface at the last commit instead (examples/drucker_prager/README.md compares).
//
// Without it, every force evaluation already return-maps every point from the committed state of the step
// (nothing plastic is committed before a step converges), so a converged step has no point with f > 0 beyond
// the return's round-off either; both solve the same discrete equations (docs/input.md, examples/drucker_prager).
#include <functional>

namespace pf {

class Model;

constexpr int kMaxYieldRounds = 50;
// On the material's dimensionless yield function (Drucker-Prager: J / J_yield - 1 at the point's pressure): a
// point past its surface by less than this is left elastic. 1e-6 is ADR's default Relative Tolerance: a relaxed
// state is resolved to about that fraction of its stresses, so a smaller excess is within the relaxation's own
// error, and admitting it would cost a whole round for a change below that error. The return map itself
// reaches f = 0 to about 1e-12 of J_yield (its dlambda tolerance is 1e-15 of J_trial/G). The default of ADR's
// 'Loading Balance Tolerance' (examples/drucker_prager/README.md: what a smaller one changes).
constexpr double kYieldTolerance = 1e-6;

// The round logic alone: relax() relaxes with the current set (may throw SolverFailure), admit() admits the
// violators of the relaxed state and returns how many (the same count on every rank). Returns the number of
// relaxations (>= 1); throws SolverFailure naming t after kMaxYieldRounds relaxations that still admit points.
int yieldRounds(const std::function<void()>& relax, const std::function<double()>& admit, double t);

// The same on a model: begins its yield rounds (empty set) and runs them. On return the model's trial state is
// the last relaxation's evaluation, with no point outside the set past tolerance, and the rounds are still
// active: the caller commits, then calls model.endYieldRounds(). On a throw the rounds are ended here.
// tol: the yield function a point outside the set may keep (dimensionless, >= 0). fromSurface: the set starts
// with the points whose committed yield function is >= -tol, else empty.
int solveWithYieldRounds(Model& model, const std::function<void()>& relax, double t, double tol, bool fromSurface);

}  // namespace pf
