#include "NoxQuasiStaticSolver.hpp"

#include <algorithm>
#include <cstdio>

#include "BreakRounds.hpp"
#include "LoadStepping.hpp"
#include "model/Model.hpp"

namespace pf {

NoxQuasiStaticSolver::NoxQuasiStaticSolver(NoxOptions o) : opt_(std::move(o)), newton_(opt_.newton) {}

NoxQuasiStaticSolver::~NoxQuasiStaticSolver() = default;

NoxQuasiStaticSolver::Outcome NoxQuasiStaticSolver::advance(Model& model, std::vector<double>& u,
                                                            std::vector<double>& duPrev, double tA, double tB,
                                                            int depth, double loadFloor) {
  const bool root = model.layout().rank() == 0;
  const std::vector<double> uA(u);
  predictStep(model, tB, u, duPrev);
  // With damage, Newton solves with the broken set frozen and the breaks are decided at each converged
  // state (BreakRounds.hpp); without, this is one Newton solve.
  Outcome o = newton_.solveWithBreaks(model, u, tB, nullptr, loadFloor);
  if (o.converged) {
    std::vector<double> f(model.numDofs());
    model.internalForce(u.data(), f.data());  // the last residual may have been a perturbed one
    model.commit();
    model.endBreakRounds();
    for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
    return o;
  }
  model.rollback();
  u = uA;
  if (depth < opt_.maxCuts) {
    if (root) std::printf("  Newton did not converge on [%g, %g] (residual %.3e, tolerance %.3e): cutting the step\n",
                          tA, tB, o.residual, o.tolerance);
    const double tm = 0.5 * (tA + tB);
    std::vector<double> half(duPrev);
    for (double& d : half) d *= 0.5;
    Outcome a = advance(model, u, half, tA, tm, depth + 1, loadFloor);
    Outcome b = advance(model, u, half, tm, tB, depth + 1, std::max(loadFloor, a.load));
    for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
    b.iterations += a.iterations;
    b.linearIterations += a.linearIterations;
    return b;
  }
  if (root) std::printf("  Newton failed on [%g, %g] after %d cuts: falling back to adaptive dynamic relaxation\n", tA,
                        tB, depth);
  predictStep(model, tB, u, duPrev);
  AdrSolver adr(opt_.fallback);
  AdrSolver::StepResult r{};
  solveWithBreakRounds(model, u, [&] {
    r = adr.relax(model, u, tB, uA, step_, loadFloor);  // throws SolverFailure if it fails too
    return true;
  }, tB);
  std::vector<double> f(model.numDofs());
  model.internalForce(u.data(), f.data());
  model.commit();
  model.endBreakRounds();
  for (std::size_t k = 0; k < u.size(); ++k) duPrev[k] = u[k] - uA[k];
  return Outcome{true, r.iterations, 0, r.residual, r.tolerance, 0.0, r.load};
}

void NoxQuasiStaticSolver::run(Model& model, std::vector<double>& u, std::vector<double>& v,
                               const std::vector<double>& times, StepObserver& observer) {
  const SolverResume* resume = takeResume();
  step_ = resume ? resume->step : 0;
  runLoadSteps(model, u, v, times, observer,
               [&](std::vector<double>& u, std::vector<double>& duPrev, double tA, double tB, double loadFloor) {
                 ++step_;
                 const Outcome o = advance(model, u, duPrev, tA, tB, 0, loadFloor);
                 StepStats s{o.iterations, o.linearIterations, o.residual, o.tolerance, o.load};
                 // Peridigm counts each NOX step() call, one even when the step starts converged (NOX then
                 // iterates 0 times), and its own QuasiStatic Newton each iteration (Peridigm.cpp).
                 s.nonlinearIterations = opt_.newton.peridigmAbsolute ? o.iterations : std::max(1, o.iterations);
                 return s;
               },
               resume);
}

}  // namespace pf
