#pragma once
// The equations of one Newton-Krylov solve on plain arrays (3 dofs per owned node), apart from any linear
// algebra library: the residual F(x) = -(f(x) + b - c (x - u~)) on free dofs and s (x - xbar) on prescribed
// ones, and its Jacobian's action. s is the preconditioner's mean free diagonal, so both kinds of rows are
// alike in scale; c = 0 without inertia.
#include <functional>
#include <vector>

#include "LoadStepping.hpp"
#include "NewtonWork.hpp"

namespace pf {

class Model;
struct Inertia;

class StepResidual {
 public:
  // work: counts and times the evaluations (null: not counted).
  StepResidual(Model& model, double t, std::vector<double> xbar, double scale, const Inertia* inertia,
               NewtonWork* work = nullptr);
  // F at x. accepted: this is an iterate's residual (NOX's own evaluation, not a perturbed one), whose
  // norms become norms(). False when a material cannot update.
  bool evaluate(const double* x, double* F, bool accepted);
  // Force and load measures at the last accepted evaluation; the inertial force -c (x - u~) counts as load.
  ResidualNorms norms() const;
  // The internal force density of the last evaluation if it was at x and the model has not been called since
  // (counted by the NewtonWork given; null without one, or otherwise): the force a new evaluation at x would give.
  const std::vector<double>* lastForceAt(const std::vector<double>& x) const;
  // Called with the norms of every accepted evaluation (the inexact-Newton tolerance hook).
  void setOnResidual(std::function<void(const ResidualNorms&)> f) { onResidual_ = std::move(f); }

 private:
  Model& model_;
  std::vector<double> xbar_;
  double scale_;
  const Inertia* inertia_;
  NewtonWork* work_;
  long lastCall_ = -1;  // work_->modelCalls() after the last successful evaluation
  std::vector<double> u_, f_, fAccepted_, b_, load_, loadAccepted_;  // load: b - c (x - u~)
  std::function<void(const ResidualNorms&)> onResidual_;
};

// J dx = -df + c dx on free rows, s dx on prescribed ones. df is the materials' exact forceDerivative where
// all have one (and `exact` was asked); otherwise a forward difference of the force with a step of 1e-7 of
// the model's shortest bond over max|dx| (a step scaled by |x|, NOX's choice, is ~0 at the first load step).
class StepTangent {
 public:
  // work: counts and times the products (null: not counted).
  StepTangent(Model& model, double scale, const Inertia* inertia, bool exact, NewtonWork* work = nullptr);
  bool exact() const { return exact_; }
  // The point x the action linearises at; false when the force cannot be evaluated there.
  bool lineariseAt(const double* x);
  // y = J dx at the last linearisation point; false on a material failure.
  bool apply(const double* dx, double* y);

 private:
  Model& model_;
  double scale_, step_ = 0;
  const Inertia* inertia_;
  bool exact_;
  NewtonWork* work_;
  std::vector<double> u_, df_, f0_, up_;
};

}  // namespace pf
