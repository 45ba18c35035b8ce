#pragma once
// Part of the NOX adapter: NOX's view of one Newton solve (a NOX::Abstract::Group on NOX's Thyra vectors over
// the Krylov solver's Tpetra space). F and J come from StepEquations, the Newton step from KrylovSolver.
// Groups cloned by NOX share the equations, the solver and one tangent; a group's x carries an id (copies share
// it), and the tangent re-linearises only when asked for at another x than the one it holds.
#include <NOX_Abstract_Group.H>
#include <NOX_Thyra_Vector.H>

#include <vector>

namespace pf {

class StepResidual;
class StepTangent;
class KrylovSolver;

// What every group of one solve shares; `linearisedAt` is the id of the x the tangent holds.
struct StepShared {
  StepResidual* residual = nullptr;
  StepTangent* tangent = nullptr;
  KrylovSolver* krylov = nullptr;
  long linearisedAt = -1;
  long nextPoint = 0;
  // J d for the last Newton direction d, from the Krylov solve's residual (J d = -F - r): the line search's
  // slope asks for exactly this product, which would cost another tangent product. jdPoint: the id of its x.
  long jdPoint = -1;
  std::vector<double> jdDirection, jd;
};

class NoxStepGroup : public NOX::Abstract::Group {
 public:
  NoxStepGroup(StepShared& shared, const std::vector<double>& x0);
  NoxStepGroup(const NoxStepGroup& source, NOX::CopyType type);

  NOX::Abstract::Group& operator=(const NOX::Abstract::Group& source) override;
  void setX(const NOX::Abstract::Vector& y) override;
  void computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d, double step) override;
  ReturnType computeF() override;
  ReturnType computeJacobian() override;
  ReturnType computeNewton(Teuchos::ParameterList& params) override;
  ReturnType applyJacobian(const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const override;
  // The Krylov solver's preconditioner (NOX's preconditioned NonlinearCG direction); no transpose.
  ReturnType applyRightPreconditioning(bool useTranspose, Teuchos::ParameterList& params,
                                       const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const override;

  bool isF() const override { return isF_; }
  bool isJacobian() const override { return isJacobian_; }
  bool isNewton() const override { return isNewton_; }
  const NOX::Abstract::Vector& getX() const override { return *x_; }
  const NOX::Abstract::Vector& getF() const override { return *f_; }
  double getNormF() const override { return normF_; }
  const NOX::Abstract::Vector& getGradient() const override;  // not defined: throws
  const NOX::Abstract::Vector& getNewton() const override { return *newton_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return f_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override;
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { return newton_; }
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type = NOX::DeepCopy) const override;

  // This rank's part of x (3 per owned node).
  void copyX(std::vector<double>& out) const;

 private:
  bool ensureLinearised() const;  // moves the shared tangent to this group's x if it holds another
  void newPoint();                // x changed: nothing computed holds any more

  StepShared& shared_;
  long point_;
  Teuchos::RCP<NOX::Thyra::Vector> x_, f_, newton_;
  double normF_ = 0;
  bool isF_ = false, isJacobian_ = false, isNewton_ = false;
};

}  // namespace pf
