#pragma once
// Implicit quasi-static load steps by NOX's line-search Newton method with a Jacobian-free Krylov solve
// (inexact: each solve asks for the reduction the force test still needs). J v is the material's exact
// derivative where it has one, else a finite difference of the force, so plastic models get their
// consistent tangent without writing one. The preconditioner (Ifpack ILU or ML) of the assembled pair
// stiffness is built once per run. A step that fails is cut in halves up to Maximum Cuts times; a step
// still failing is relaxed by ADR, and the fallback is logged.
#include <memory>

#include "AdrSolver.hpp"
#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

struct NoxOptions {
  double relativeTolerance = 1e-10;  // of the load scale (reaction + body force), as ADR's
  double absoluteTolerance = 0.0;    // on the residual force-density norm (Peridigm's unit)
  int maxIterations = 30;            // Newton iterations per (sub)step
  int maxCuts = 4;                   // a failing step is halved at most this many times
  bool verbose = false;              // print NOX's residual history
  // The preconditioner matrix keeps only each node's bonds up to this many times its shortest bond
  // (the grid spacing), stiffened to keep the second moment (the smooth-mode stiffness). Measured: at
  // delta/dx = 5 a radius of 3 dx halves the wall time (20 % more Krylov iterations); at delta/dx = 3
  // it keeps every bond, and cutting further there cost more iterations than it saved.
  double precBondRadius = 3.0;
  ParamTree nox;                     // "Direction", "Line Search", "Printing", ... passed to NOX
  AdrOptions fallback;
};

class NoxQuasiStaticSolver : public Solver {
 public:
  explicit NoxQuasiStaticSolver(NoxOptions o);
  static SolverEntry entry();           // "NOXQuasiStatic"
  static SolverEntry peridigmEntry();   // Peridigm's "QuasiStatic" (Newton), served by the same engine
  ~NoxQuasiStaticSolver() override;
  std::string name() const override { return "NOXQuasiStatic (Newton-Krylov)"; }
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;

 private:
  struct Outcome {
    bool converged = false;
    int iterations = 0, linearIterations = 0;
    double residual = 0, tolerance = 0, load = 0;
  };
  Outcome newton(Model& model, std::vector<double>& u, double t, double loadFloor);
  // Solves [tA, tB] from the converged u at tA, cutting or falling back as needed; commits its end.
  Outcome advance(Model& model, std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB, int depth,
                  double loadFloor);

  NoxOptions opt_;
  long step_ = 0;  // the load step being solved, for messages
  struct Linear;                       // Epetra map, pair stiffness and its preconditioner (the .cpp)
  std::unique_ptr<Linear> linear_;     // built on first use, kept for the whole run
  double scale_ = 1.0;                 // the pair stiffness' mean diagonal: the weight of prescribed rows
};

}  // namespace pf
