#pragma once
// What the Newton-Krylov engine did over a run, counted where it happens: deterministic work counts (they compare
// builds and machines) and this rank's wall seconds per part (where a step's time goes; issue 35's profile).
// Printed by the solvers that own an engine at the end of their run.
#include <chrono>
#include <string>

namespace pf {

struct NewtonWork {
  long newtonIterations = 0, krylovIterations = 0;
  long residuals = 0;                   // evaluations of F(x), the line search's included
  long tangentProducts = 0;             // J dx: the exact derivative, or a difference of two forces
  long linearisations = 0;              // Newton points the tangent was formed at (Model::lineariseAt; FD: its base force)
  double tangentBytes = 0;              // the most memory the kept tangent held on rank 0 (Model::linearisationBytes)
  long preconditionerApplications = 0;  // M^-1 r inside GMRES (right preconditioning) and for NLCG
  long preconditionerBuilds = 0;
  double seconds = 0;  // in the engine's solves, the preconditioner's build included
  double residualSeconds = 0, tangentSeconds = 0, linearisationSeconds = 0, preconditionerSeconds = 0, buildSeconds = 0;
  double krylovSeconds = 0;  // in GMRES, its products and preconditioner applications included
  // The model calls so far (each residual, product and linearisation is one): the sequence number of the last one.
  long modelCalls() const { return residuals + tangentProducts + linearisations; }
  // "NOX work: N Newton iterations, ..." and the seconds of each part with its share of `seconds`.
  std::string summary() const;
};

// Adds the wall seconds from construction to destruction to `into` (null: nothing).
class WorkTimer {
 public:
  explicit WorkTimer(double* into) : into_(into), start_(std::chrono::steady_clock::now()) {}
  ~WorkTimer() {
    if (into_) *into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  WorkTimer(const WorkTimer&) = delete;
  WorkTimer& operator=(const WorkTimer&) = delete;

 private:
  double* into_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace pf
