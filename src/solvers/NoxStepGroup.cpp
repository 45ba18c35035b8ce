#include "NoxStepGroup.hpp"

#include <Thyra_SpmdVectorBase.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <algorithm>
#include <stdexcept>

#include "KrylovSolver.hpp"
#include "StepEquations.hpp"

namespace pf {
namespace {

// This rank's entries of a NOX vector of the Krylov solver's space (a Tpetra vector behind Thyra's SPMD face).
Teuchos::ArrayRCP<double> local(NOX::Abstract::Vector& v) {
  auto spmd = Teuchos::rcp_dynamic_cast<Thyra::SpmdVectorBase<double>>(
      dynamic_cast<NOX::Thyra::Vector&>(v).getThyraRCPVector(), true);
  Teuchos::ArrayRCP<double> data;
  spmd->getNonconstLocalData(Teuchos::outArg(data));
  return data;
}

Teuchos::ArrayRCP<const double> local(const NOX::Abstract::Vector& v) {
  auto spmd = Teuchos::rcp_dynamic_cast<const Thyra::SpmdVectorBase<double>>(
      dynamic_cast<const NOX::Thyra::Vector&>(v).getThyraRCPVector(), true);
  Teuchos::ArrayRCP<const double> data;
  spmd->getLocalData(Teuchos::outArg(data));
  return data;
}

Teuchos::RCP<NOX::Thyra::Vector> newVector(const KrylovSolver& krylov) {
  return Teuchos::rcp(new NOX::Thyra::Vector(Thyra::createMember(krylov.space())));
}

}  // namespace

NoxStepGroup::NoxStepGroup(StepShared& shared, const std::vector<double>& x0)
    : shared_(shared), point_(shared.nextPoint++), x_(newVector(*shared.krylov)), f_(newVector(*shared.krylov)),
      newton_(newVector(*shared.krylov)) {
  Teuchos::ArrayRCP<double> x = local(*x_);
  std::copy(x0.begin(), x0.end(), x.begin());
}

NoxStepGroup::NoxStepGroup(const NoxStepGroup& source, NOX::CopyType type)
    : shared_(source.shared_), point_(type == NOX::DeepCopy ? source.point_ : shared_.nextPoint++),
      x_(Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(source.x_->clone(type), true)),
      f_(Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(source.f_->clone(type), true)),
      newton_(Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(source.newton_->clone(type), true)) {
  if (type == NOX::DeepCopy) {
    normF_ = source.normF_;
    isF_ = source.isF_;
    isJacobian_ = source.isJacobian_;
    isNewton_ = source.isNewton_;
  }
}

void NoxStepGroup::newPoint() {
  isF_ = isJacobian_ = isNewton_ = false;
  point_ = shared_.nextPoint++;
}

NOX::Abstract::Group& NoxStepGroup::operator=(const NOX::Abstract::Group& source) {
  const auto& src = dynamic_cast<const NoxStepGroup&>(source);
  if (&src == this) return *this;
  *x_ = *src.x_;
  *f_ = *src.f_;
  *newton_ = *src.newton_;
  point_ = src.point_;
  normF_ = src.normF_;
  isF_ = src.isF_;
  isJacobian_ = src.isJacobian_;
  isNewton_ = src.isNewton_;
  return *this;
}

void NoxStepGroup::setX(const NOX::Abstract::Vector& y) {
  newPoint();
  *x_ = y;
}

void NoxStepGroup::computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d, double step) {
  newPoint();
  x_->update(1.0, dynamic_cast<const NoxStepGroup&>(grp).getX(), step, d, 0.0);
}

NOX::Abstract::Group::ReturnType NoxStepGroup::computeF() {
  if (isF_) return Ok;
  Teuchos::ArrayRCP<const double> x = local(static_cast<const NOX::Abstract::Vector&>(*x_));
  Teuchos::ArrayRCP<double> F = local(*f_);
  if (!shared_.residual->evaluate(x.getRawPtr(), F.getRawPtr(), true)) return Failed;
  normF_ = f_->norm();
  isF_ = true;
  return Ok;
}

bool NoxStepGroup::ensureLinearised() const {
  if (shared_.linearisedAt == point_) return true;
  Teuchos::ArrayRCP<const double> x = local(static_cast<const NOX::Abstract::Vector&>(*x_));
  if (!shared_.tangent->lineariseAt(x.getRawPtr())) return false;
  shared_.linearisedAt = point_;
  return true;
}

NOX::Abstract::Group::ReturnType NoxStepGroup::computeJacobian() {
  if (isJacobian_ && shared_.linearisedAt == point_) return Ok;
  if (!ensureLinearised()) return Failed;
  isJacobian_ = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType NoxStepGroup::applyJacobian(const NOX::Abstract::Vector& input,
                                                             NOX::Abstract::Vector& result) const {
  if (!isJacobian_) return BadDependency;
  Teuchos::ArrayRCP<const double> in = local(input);
  Teuchos::ArrayRCP<double> out = local(result);
  // jdPoint is the same on every rank, so every rank joins the collective comparison or none does.
  if (shared_.jdPoint == point_ &&
      shared_.krylov->onEveryRank(shared_.jdDirection.size() == static_cast<std::size_t>(in.size()) &&
                                  std::equal(in.begin(), in.end(), shared_.jdDirection.begin()))) {
    std::copy(shared_.jd.begin(), shared_.jd.end(), out.begin());
    return Ok;
  }
  if (!ensureLinearised()) return BadDependency;
  return shared_.tangent->apply(in.getRawPtr(), out.getRawPtr()) ? Ok : Failed;
}

NOX::Abstract::Group::ReturnType NoxStepGroup::computeNewton(Teuchos::ParameterList& params) {
  if (isNewton_) return Ok;
  if (!isF_ && computeF() != Ok) return Failed;
  if (computeJacobian() != Ok) return Failed;
  NOX::Thyra::Vector rhs(*f_);
  rhs.scale(-1.0);
  Teuchos::ArrayRCP<const double> b = local(static_cast<const NOX::Abstract::Vector&>(rhs));
  Teuchos::ArrayRCP<double> dx = local(*newton_);
  const TangentAction action = [this](const double* in, double* out) {
    return ensureLinearised() && shared_.tangent->apply(in, out);
  };
  std::vector<double>& r = shared_.jd;
  r.resize(static_cast<std::size_t>(b.size()));
  const KrylovOutcome k = shared_.krylov->solve(action, b.getRawPtr(), dx.getRawPtr(), params, r.data());
  shared_.jdPoint = -1;
  if (!k.failed) {  // r = b - J dx: J dx = b - r
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = b[i] - r[i];
    shared_.jdDirection.assign(dx.begin(), dx.end());
    shared_.jdPoint = point_;
  }
  // The counts under the names NOX's linear systems use (NewtonKrylov reads the total).
  Teuchos::ParameterList& out = params.sublist("Output");
  out.set("Number of Linear Iterations", k.iterations);
  out.set("Total Number of Linear Iterations", out.get<int>("Total Number of Linear Iterations", 0) + k.iterations);
  if (k.failed) return Failed;
  isNewton_ = true;
  return k.converged ? Ok : NotConverged;
}

NOX::Abstract::Group::ReturnType NoxStepGroup::applyRightPreconditioning(bool useTranspose,
                                                                       Teuchos::ParameterList& params,
                                                                       const NOX::Abstract::Vector& input,
                                                                       NOX::Abstract::Vector& result) const {
  if (useTranspose) return NotDefined;  // the pair-stiffness preconditioners are symmetric, but NOX's NLCG never asks
  Teuchos::ArrayRCP<const double> in = local(input);
  Teuchos::ArrayRCP<double> out = local(result);
  shared_.krylov->applyPreconditioner(in.getRawPtr(), out.getRawPtr(), params);
  return Ok;
}

const NOX::Abstract::Vector& NoxStepGroup::getGradient() const {
  throw std::logic_error("NoxStepGroup: no gradient (the line search uses J d instead)");
}

Teuchos::RCP<const NOX::Abstract::Vector> NoxStepGroup::getGradientPtr() const {
  throw std::logic_error("NoxStepGroup: no gradient (the line search uses J d instead)");
}

Teuchos::RCP<NOX::Abstract::Group> NoxStepGroup::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new NoxStepGroup(*this, type));
}

void NoxStepGroup::copyX(std::vector<double>& out) const {
  Teuchos::ArrayRCP<const double> x = local(static_cast<const NOX::Abstract::Vector&>(*x_));
  std::copy(x.begin(), x.end(), out.begin());
}

}  // namespace pf
