#pragma once
// Peridigm's "Implicit": Newmark-beta time integration with a fixed step, each step's
//   rho (u - u~) / (beta dt^2) = f(u) + b(t)     (u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n)
// solved by the Newton-Krylov engine (NewtonKrylov.hpp) to Peridigm's test beta dt^2 |rho a - f - b| <=
// Absolute Tolerance; a step that does not converge throws SolverFailure (nothing unconverged is reported).
#include "NewtonKrylov.hpp"
#include "Solver.hpp"
#include "core/SolverEntry.hpp"

namespace pf {

struct ImplicitOptions {
  double dt = 0.0;                  // Fixed dt (required)
  double beta = 0.25, gamma = 0.5;  // Newmark's; 1/4, 1/2: the trapezoidal rule (energy-conserving, linear)
  double absoluteTolerance = 1e-6;  // Peridigm's, on |beta dt^2 (rho a - f - b)| over free dofs
  bool initialEquationOfMotion = false;  // a0 = (f + b)/rho (Newmark's) instead of Peridigm's a0 = 0
  NewtonKrylovOptions newton;       // maxIterations, preconditioner, NOX's lists; tolerances set by run()
  std::string where;                // the deck list, for warnings ("input.xml: Solver/Implicit")
};

class ImplicitSolver : public Solver {
 public:
  explicit ImplicitSolver(ImplicitOptions o);
  static SolverEntry entry();  // "Implicit"
  std::string name() const override { return "Implicit (Newmark-beta, Newton-Krylov)"; }
  void check(const Model& model) const override;  // warns when beta < gamma / 2 (conditionally stable)
  void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
           StepObserver& observer) override;
  // Peridigm's step count: floor((t1 - t0) / dt), the quotient's round-off forgiven (5e-5 / 1e-5 is 5).
  static long stepCount(double t0, double t1, double dt);

 private:
  ImplicitOptions opt_;
};

}  // namespace pf
