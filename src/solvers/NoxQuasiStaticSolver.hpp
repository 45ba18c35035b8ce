#pragma once
// Implicit quasi-static load steps, each solved by the Newton-Krylov engine (NewtonKrylov.hpp: NOX's
// line-search Newton, Jacobian-free GMRES with the material's exact derivative or a finite difference,
// the pair-stiffness preconditioner built once per run). A step that fails is cut in halves up to
// Maximum Cuts times; a step still failing is relaxed by ADR, and the fallback is logged. With `Solve For
// Temperature` each converged step is followed by a Backward Euler step of the Temperature field over the same
// interval (staggered, ImplicitFieldStep.hpp): the mechanics of a step sees the temperature of its start.
#include <memory>

#include "AdaptiveLoadStepping.hpp"
#include "AdrSolver.hpp"
#include "ImplicitFieldStep.hpp"
#include "NewtonKrylov.hpp"
#include "SolvedStates.hpp"
#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

struct NoxOptions {
  NewtonKrylovOptions newton;  // tolerances, iterations per (sub)step, preconditioner, NOX's lists
  int maxCuts = 4;             // a failing step is halved at most this many times
  bool quadraticPredictor = false;  // `Predictor` = `Quadratic` (SolvedStates.hpp)
  AdrOptions fallback;
  AdaptiveLoadStepping adaptive;  // Peridigm's QuasiStatic `Adaptive Load-Stepping` (instead of cuts and ADR)
};

class NoxQuasiStaticSolver : public Solver {
 public:
  explicit NoxQuasiStaticSolver(NoxOptions o);
  static SolverEntry entry();           // "NOXQuasiStatic"
  static SolverEntry peridigmEntry();   // Peridigm's "QuasiStatic" (Newton), served by the same engine
  ~NoxQuasiStaticSolver() override;
  std::string name() const override { return "NOXQuasiStatic (Newton-Krylov)"; }
  void check(const Model& model) const override;  // the Temperature step's verdict, when the deck solves for it
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;

 private:
  using Outcome = NewtonOutcome;
  // Solves [tA, tB] from the converged u at tA, cutting or falling back as needed; commits its end.
  Outcome advance(Model& model, std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB, int depth,
                  double loadFloor);

  // Peridigm's adaptive load stepping (AdaptiveLoadStepping.hpp) in place of the cuts and the ADR fallback.
  void runAdaptive(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
                   StepObserver& observer);

  // The Temperature step after each converged mechanics step, when the deck solves for it (else null).
  void startHeat(Model& model);
  ImplicitFieldOptions heatOptions() const;
  void printHeatWork(const Model& model) const;
  static constexpr double kHeatRelativeTolerance = 1e-10;  // of each heat step's initial residual
  // A step's end, converged at u: its heat step (if any), then the model's state committed.
  void commitStep(Model& model, const std::vector<double>& u, const std::vector<double>& uA,
                  std::vector<double>& duPrev, double tA, double tB);

  NoxOptions opt_;
  std::unique_ptr<ImplicitFieldStep> heat_;
  std::vector<double> committedForce_;  // the last committed step's internal force (before its heat step)
  SolvedStates solved_;  // the quadratic predictor's states (kept with `Predictor` = `Quadratic` only)
  long step_ = 0;          // the load step being solved, for messages
  NewtonKrylov newton_;    // its preconditioner is built on the first step and kept for the whole run
};

}  // namespace pf
