#pragma once
// Pieces shared by the quasi-static solvers (relaxation and Newton): the load-step predictor and the
// residual measures their convergence tests use, so both judge a step the same way.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace pf {

class Model;
class StepObserver;
struct SolverResume;
struct SolvedStates;

// What a solver keeps from one load step to the next beyond the loop's own increment and peak load: vectors of n values
// and scalars it owns. runLoadSteps carries their current values in every report (a checkpoint stores them) and, on a
// resume, restores each one the checkpoint has (one it lacks keeps the solver's value).
struct CarriedState {
  std::vector<std::pair<std::string, std::vector<double>*>> vectors;
  std::vector<std::pair<std::string, double*>> scalars;
};

struct ResidualNorms {
  double residual = 0;         // || (f + b) V || over free dofs (force)
  double load = 0;             // || f V || over prescribed dofs (reaction) + || b V ||
  double residualDensity = 0;  // || f + b || over free dofs (force density)
  // Peridigm's QuasiStatic measure (Peridigm.cpp, computeQuasiStaticResidual): ||r||_2 + 20 ||r||_inf of the force
  // r = (f + b) V over free dofs, which its 'Absolute Tolerance' bounds.
  double peridigmQuasiStatic = 0;
};

// f: internal force density, b: body force density, 3 per owned node; reduced over all ranks.
ResidualNorms residualNorms(const Model& model, const std::vector<double>& f, const std::vector<double>& b);

// Sets the prescribed components of u to their values at t and moves the free ones by the previous
// step's increment scaled by how the prescribed increment continues it (exact for a linear problem
// under proportional loading; after a reversal it extrapolates backwards, as the load does).
// states (or null): the quadratic through the last solved states where it applies (SolvedStates.hpp, predictQuadratic).
void predictStep(const Model& model, double t, std::vector<double>& u, const std::vector<double>& duPrev,
                 const SolvedStates* states = nullptr);

struct StepStats {
  int iterations = 0;
  int linearIterations = -1;  // -1: the solver has no inner linear solve
  double residual = 0, tolerance = 0;
  double load = 0;  // the converged step's load scale (ResidualNorms::load)
  int rounds = -1;  // loading-balance relaxations of the step (YieldRounds.hpp); -1: not used
  int nonlinearIterations = 0;  // StepReport::nonlinearIterations
  int outputEveryFactor = 1;    // StepReport::outputEveryFactor
  // The internal force density of the committed state, when the solver kept it: reported instead of a new evaluation
  // at the step's end, which would see a field the solver advanced after the mechanics (a staggered temperature) and
  // present a stress the mechanics never converged to.
  const std::vector<double>* force = nullptr;
  // Retry: the step did not converge and the solver changed the times list (a shorter step inserted); solve the
  // step again from the same state. Stop: end the load stepping here (the state is the last reported step's).
  enum class Outcome { Converged, Retry, Stop };
  Outcome outcome = Outcome::Converged;
};

// The load scale a step's relative tolerance multiplies: the step's own, but never below the largest a
// converged step has carried (loadFloor). An unloaded body holds residual stresses that the loads before
// made; with the reactions and body forces gone, a tolerance relative to them alone falls below round-off.
inline double loadScale(const ResidualNorms& r, double loadFloor) { return r.load > loadFloor ? r.load : loadFloor; }

// The quasi-static load-step loop both implicit solvers share: reports the initial state at times[0], then
// for each step k = 1 .. times.size()-1 calls solveStep(u, duPrev, times[k-1], times[k], loadFloor), which must
// leave u converged at times[k] (judged with loadScale(norms, loadFloor)), the state committed and duPrev = the
// step's increment; loadFloor is the largest StepStats::load so far (carried as "Peak Load"); prints one progress line,
// reports the step with the load-step rate du/dt as velocity (as Peridigm's quasi-static solvers write it).
// resume (or null): continue after resume->step, whose increment it carries as "Increment" (a restart);
// each report carries duPrev under that name. times may change during the loop (StepStats::Outcome::Retry).
// own (or null): the solver's CarriedState.
void runLoadSteps(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
                  StepObserver& observer,
                  const std::function<StepStats(std::vector<double>& u, std::vector<double>& duPrev, double tA,
                                                double tB, double loadFloor)>& solveStep,
                  const SolverResume* resume, const CarriedState* own = nullptr);

}  // namespace pf
