#include "KrylovSolver.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockGmresSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <type_traits>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

// Belos' Tpetra library already holds GMRES for Tpetra's default vector and operator (its solver factory instantiates
// it): taken from there instead of instantiated again here, which took half of this file's 41 s compile (the largest
// of the build; docs/benchmark-log.md, session 25).
extern template class Belos::PseudoBlockGmresSolMgr<double, Tpetra::MultiVector<double>, Tpetra::Operator<double>>;

#include <algorithm>

#include "PairStiffness.hpp"
#include "RigidBodyModes.hpp"
#include "NoxParameters.hpp"
#include "model/Model.hpp"
#include "parallel/TpetraSupport.hpp"

namespace pf {
namespace {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using MV = Tpetra::MultiVector<double>;
using OP = Tpetra::Operator<double>;
using Matrix = Tpetra::CrsMatrix<double>;

struct ActionFailed {};

// The tangent as a Tpetra operator: Y = alpha J X + beta Y, column by column through the array action.
class ActionOperator : public OP {
 public:
  ActionOperator(Teuchos::RCP<const Map> map, const TangentAction& action) : map_(std::move(map)), action_(action) {}
  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    const std::size_t n = X.getLocalLength();
    tmp_.resize(n);
    for (std::size_t col = 0; col < X.getNumVectors(); ++col) {
      Teuchos::ArrayRCP<const double> x = X.getData(col);
      if (!action_(x.getRawPtr(), tmp_.data())) throw ActionFailed();
      Teuchos::ArrayRCP<double> y = Y.getDataNonConst(col);
      for (std::size_t k = 0; k < n; ++k) y[k] = alpha * tmp_[k] + (beta == 0.0 ? 0.0 : beta * y[k]);
    }
  }

 private:
  Teuchos::RCP<const Map> map_;
  const TangentAction& action_;
  mutable std::vector<double> tmp_;
};

Teuchos::RCP<MV> wrap(const Teuchos::RCP<const Map>& map, const double* data) {
  return Teuchos::rcp(new MV(hostView<MV>(map, data)));  // a Tpetra copy is a shallow one: still the array
}

// The rigid-body modes (RigidBodyModes.hpp) as a Tpetra multivector on the Newton vectors' map.
Teuchos::RCP<MV> nearNullSpace(const Teuchos::RCP<const Map>& map, const Model& model) {
  const RigidBodyModes modes = rigidBodyModes(model.coordinates(), model.numOwned(), model.layout().comm());
  const std::size_t n = 3 * static_cast<std::size_t>(model.numOwned());
  auto B = Teuchos::rcp(new MV(map, modes.count));
  for (int k = 0; k < modes.count; ++k) {
    Teuchos::ArrayRCP<double> b = B->getDataNonConst(k);
    std::copy(modes.values.begin() + k * n, modes.values.begin() + (k + 1) * n, b.getRawPtr());
  }
  return B;
}

// MueLu's smoothed aggregation with ML's settings that Periforge measured (3 dofs per point, one symmetric
// Gauss-Seidel sweep: one more Krylov iteration, 30 % less time) and the rigid-body near-null space (without it
// MueLu takes the translations alone, which an elastic body's aggregates cannot rotate with); a "MueLu" sub-list
// overrides them.
Teuchos::RCP<OP> buildMueLu(const Teuchos::RCP<Matrix>& A, const Teuchos::RCP<MV>& nullspace,
                            Teuchos::ParameterList& linearSolver) {
  Teuchos::ParameterList p;
  if (!nullspace.is_null()) p.sublist("user data").set("Nullspace", nullspace);
  p.set("verbosity", "none");
  p.set("multigrid algorithm", "sa");
  p.set("number of equations", 3);
  p.set("coarse: max size", 500);
  p.set("smoother: type", "RELAXATION");
  p.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  p.sublist("smoother: params").set("relaxation: sweeps", 1);
  if (linearSolver.isSublist("MueLu")) p.setParameters(linearSolver.sublist("MueLu"));
  Teuchos::RCP<OP> op = A;
  return MueLu::CreateTpetraPreconditioner<double, Map::local_ordinal_type, GO, Map::node_type>(op, p);
}

// Ifpack's parameter names as Ifpack2's ("fact: level-of-fill" is RILUK's "fact: iluk level-of-fill"); an
// overlap > 0 puts the additive Schwarz around the factorisation, as Ifpack's did.
Teuchos::RCP<OP> buildIfpack2(const Teuchos::RCP<Matrix>& A, Teuchos::ParameterList& linearSolver,
                              const std::string& type) {
  using Row = Tpetra::RowMatrix<double>;
  Teuchos::ParameterList inner;
  if (linearSolver.isSublist("Ifpack")) {
    const Teuchos::ParameterList& ifpack = linearSolver.sublist("Ifpack");
    for (auto e = ifpack.begin(); e != ifpack.end(); ++e) {
      const std::string& name = ifpack.name(e);
      inner.setEntry(name == "fact: level-of-fill" ? "fact: iluk level-of-fill" : name, ifpack.entry(e));
    }
  }
  // AztecOO's overlap is a level; Peridigm's decks also give it as a bool (false: none).
  const int overlap = linearSolver.isType<bool>("Overlap") ? (linearSolver.get<bool>("Overlap") ? 1 : 0)
                                                            : linearSolver.get<int>("Overlap", 0);
  Ifpack2::Factory factory;
  Teuchos::RCP<Ifpack2::Preconditioner<double>> prec;
  if (overlap > 0) {
    prec = factory.create<Row>("SCHWARZ", A);
    Teuchos::ParameterList schwarz;
    schwarz.set("schwarz: overlap level", overlap);
    schwarz.set("inner preconditioner name", type);
    schwarz.set("inner preconditioner parameters", inner);
    prec->setParameters(schwarz);
  } else {
    prec = factory.create<Row>(type, A);
    prec->setParameters(inner);
  }
  prec->initialize();
  prec->compute();
  return prec;
}

}  // namespace

struct KrylovSolver::Impl {
  Teuchos::RCP<const Map> map;
  Teuchos::RCP<Matrix> matrix;  // the pair stiffness (+ shift)
  Teuchos::RCP<OP> prec;        // built on the first solve; null for "None"
  Teuchos::RCP<MV> nullspace;   // the rigid-body modes, for MueLu; released once the preconditioner is built
  bool precBuilt = false;
  double scale = 1.0;
  std::string where;
};

KrylovSolver::KrylovSolver(const Model& model, double precBondRadius, const std::vector<double>* shift,
                           std::string where)
    : impl_(std::make_unique<Impl>()) {
  impl_->where = std::move(where);
  ensureKokkos();
  const auto comm = teuchosComm(model.layout().comm());
  static_assert(std::is_same<GO, long long>::value, "the pair rows' columns are passed to Tpetra as they are");
  std::vector<GO> gids;
  impl_->scale = pairStiffnessRows(
      model, precBondRadius, shift,
      [&](const std::vector<long long>& rows, const std::vector<std::size_t>& counts) {
        gids.assign(rows.begin(), rows.end());
        const Tpetra::global_size_t any = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
        impl_->map = Teuchos::rcp(new Map(any, Teuchos::ArrayView<const GO>(gids.data(), gids.size()), 0, comm));
        Teuchos::Array<std::size_t> perRow(counts.begin(), counts.end());
        impl_->matrix = Teuchos::rcp(new Matrix(impl_->map, perRow()));
      },
      [&](std::size_t r, const long long* columns, const double* values, std::size_t n) {
        impl_->matrix->insertGlobalValues(gids[r], Teuchos::ArrayView<const GO>(columns, n),
                                          Teuchos::ArrayView<const double>(values, n));
      });
  impl_->matrix->fillComplete();
  impl_->nullspace = nearNullSpace(impl_->map, model);
}

KrylovSolver::~KrylovSolver() = default;

double KrylovSolver::scale() const { return impl_->scale; }

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> KrylovSolver::space() const {
  return Thyra::createVectorSpace<double>(impl_->map);
}

void KrylovSolver::ensurePreconditioner(Teuchos::ParameterList& linearSolver) {
  Impl& s = *impl_;
  if (s.precBuilt) return;
  // The deck's choice was validated when it was read (checkLinearSolver).
  const LinearSolverChoice choice = linearSolverChoice(linearSolver, s.where);
  if (choice.preconditioner == LinearSolverChoice::Preconditioner::MueLu)
    s.prec = buildMueLu(s.matrix, s.nullspace, linearSolver);
  else if (choice.preconditioner == LinearSolverChoice::Preconditioner::Ifpack2)
    s.prec = buildIfpack2(s.matrix, linearSolver, choice.ifpack2Type);
  s.nullspace = Teuchos::null;  // MueLu keeps what it uses; the other choices never read it
  s.precBuilt = true;
}

void KrylovSolver::applyPreconditioner(const double* in, double* out, Teuchos::ParameterList& linearSolver) {
  ensurePreconditioner(linearSolver);
  const Impl& s = *impl_;
  const std::size_t n = s.map->getNodeNumElements();
  if (s.prec.is_null()) {
    std::copy(in, in + n, out);
    return;
  }
  Teuchos::RCP<MV> X = wrap(s.map, in), Y = wrap(s.map, out);
  s.prec->apply(*X, *Y);
}

KrylovOutcome KrylovSolver::solve(const TangentAction& J, const double* rhs, double* dx,
                                  Teuchos::ParameterList& linearSolver) {
  Impl& s = *impl_;
  ensurePreconditioner(linearSolver);
  const int maxIterations = linearSolver.get<int>("Max Iterations", 800);
  const int krylov = std::max(1, std::min(linearSolver.get<int>("Size of Krylov Subspace", 200), maxIterations));
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", linearSolver.get<double>("Tolerance", 1e-9));
  params->set("Maximum Iterations", maxIterations);
  params->set("Num Blocks", krylov);
  params->set("Maximum Restarts", maxIterations / krylov + 1);
  // |r| / |r0| with r0 = rhs (dx starts at 0): the forcing term of the inexact Newton step, unpreconditioned
  // because the preconditioner sits on the right.
  params->set("Implicit Residual Scaling", "Norm of Initial Residual");
  params->set("Explicit Residual Scaling", "Norm of Initial Residual");
  params->set("Verbosity", static_cast<int>(Belos::Errors));

  std::fill(dx, dx + s.map->getNodeNumElements(), 0.0);
  auto op = Teuchos::rcp(new ActionOperator(s.map, J));
  Teuchos::RCP<MV> X = wrap(s.map, dx), B = wrap(s.map, rhs);
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(op, X, B));
  if (!s.prec.is_null()) problem->setRightPrec(s.prec);
  problem->setProblem();
  // The problem first, then the parameters: the (problem, list) constructor's order; that constructor is not among
  // the library's members (the extern template above).
  Belos::PseudoBlockGmresSolMgr<double, MV, OP> gmres;
  gmres.setProblem(problem);
  gmres.setParameters(params);
  KrylovOutcome out;
  try {
    out.converged = gmres.solve() == Belos::Converged;
  } catch (const ActionFailed&) {
    out.failed = true;
  }
  out.iterations = gmres.getNumIters();
  return out;
}

}  // namespace pf
