#include "KrylovSolver.hpp"

#include <Ifpack2_Factory.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_ParameterListExceptions.hpp>
#include <type_traits>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>


#include <algorithm>
#include <sstream>

#include "Gmres.hpp"
#include "PairStiffness.hpp"
#include "MueLuPreconditioner.hpp"
#include "NewtonWork.hpp"
#include "NoxParameters.hpp"
#include "Solver.hpp"
#include "core/InputError.hpp"
#include "model/Model.hpp"
#include "parallel/TpetraSupport.hpp"

namespace pf {
namespace {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using MV = Tpetra::MultiVector<double>;
using OP = Tpetra::Operator<double>;
using Matrix = Tpetra::CrsMatrix<double>;

// A Teuchos exception's text without its source location and throw count, on one line: "Error, the parameter
// {name=...} in the parameter (sub)list ... was not found in the list of valid parameters!" (the list that follows
// a blank line is left out).
std::string libraryMessage(const std::exception& e) {
  std::istringstream in(e.what());
  std::string line, out;
  while (std::getline(in, line)) {
    const bool skip = line.rfind("Throw ", 0) == 0 || line.find(".hpp:") != std::string::npos ||
                      line.find(".cpp:") != std::string::npos;
    if (line.empty() || skip) {
      if (!out.empty()) break;
      continue;
    }
    out += (out.empty() ? "" : " ") + line;
  }
  return out.empty() ? std::string(e.what()) : out;
}

// The preconditioner as GMRES sees it: each application counted and timed (NewtonWork).
class CountedOperator : public OP {
 public:
  CountedOperator(Teuchos::RCP<OP> inner, NewtonWork& work) : inner_(std::move(inner)), work_(work) {}
  Teuchos::RCP<const Map> getDomainMap() const override { return inner_->getDomainMap(); }
  Teuchos::RCP<const Map> getRangeMap() const override { return inner_->getRangeMap(); }
  void apply(const MV& X, MV& Y, Teuchos::ETransp mode, double alpha, double beta) const override {
    const WorkTimer timer(&work_.preconditionerSeconds);
    work_.preconditionerApplications += static_cast<long>(X.getNumVectors());
    inner_->apply(X, Y, mode, alpha, beta);
  }

 private:
  Teuchos::RCP<OP> inner_;
  NewtonWork& work_;
};

Teuchos::RCP<MV> wrap(const Teuchos::RCP<const Map>& map, const double* data) {
  return Teuchos::rcp(new MV(hostView<MV>(map, data)));  // a Tpetra copy is a shallow one: still the array
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
  MueLuInputs mueLu;            // released once the preconditioner is built
  bool precBuilt = false;
  double scale = 1.0;
  std::string where;
  NewtonWork* work = nullptr;
};

KrylovSolver::KrylovSolver(const Model& model, double precBondRadius, const std::vector<double>* shift,
                           std::string where, NewtonWork* work)
    : impl_(std::make_unique<Impl>()) {
  impl_->where = std::move(where);
  impl_->work = work;
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
  impl_->mueLu = mueLuInputs(impl_->map, model);
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
  // A library's refusal ends the run with its own words: a parameter of the deck's "MueLu" or "Ifpack" sub-list it
  // does not take is an input error; anything else (a factorisation that breaks down) a solver failure. Inside the
  // Newton solve either would read as a step that did not converge and fall back to dynamic relaxation unsaid.
  // Every rank learns of a failure on one (an Ifpack2 factorisation is local), so none waits in a later collective.
  const std::string at = s.where + "/Direction/Newton/Linear Solver: the preconditioner could not be built: ";
  const WorkTimer timer(s.work ? &s.work->buildSeconds : nullptr);
  if (s.work) ++s.work->preconditionerBuilds;
  int failure = 0;  // 1: a parameter the library does not take, 2: another failure
  std::string message;
  try {
    if (choice.preconditioner == LinearSolverChoice::Preconditioner::MueLu)
      s.prec = buildMueLu(s.matrix, s.mueLu, linearSolver);
    else if (choice.preconditioner == LinearSolverChoice::Preconditioner::Ifpack2)
      s.prec = buildIfpack2(s.matrix, linearSolver, choice.ifpack2Type);
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {
    failure = 1;
    message = libraryMessage(e);
  } catch (const std::exception& e) {
    failure = 2;
    message = libraryMessage(e);
  }
  int anyFailure = 0;
  Teuchos::reduceAll(*s.map->getComm(), Teuchos::REDUCE_MAX, failure, Teuchos::outArg(anyFailure));
  if (anyFailure == 1) throw InputError(at + (message.empty() ? "on another rank" : message));
  if (anyFailure == 2) throw SolverFailure(at + (message.empty() ? "on another rank" : message));
  s.mueLu = MueLuInputs();  // MueLu keeps what it uses; the other choices never read it
  if (s.work && !s.prec.is_null()) s.prec = Teuchos::rcp(new CountedOperator(s.prec, *s.work));
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

bool KrylovSolver::onEveryRank(bool local) const {
  int all = 0;
  Teuchos::reduceAll(*impl_->map->getComm(), Teuchos::REDUCE_MIN, local ? 1 : 0, Teuchos::outArg(all));
  return all == 1;
}

KrylovOutcome KrylovSolver::solve(const TangentAction& J, const double* rhs, double* dx,
                                  Teuchos::ParameterList& linearSolver, double* linearResidual) {
  Impl& s = *impl_;
  ensurePreconditioner(linearSolver);
  const WorkTimer timer(s.work ? &s.work->krylovSeconds : nullptr);
  const int maxIterations = linearSolver.get<int>("Max Iterations", 800);
  const int krylov = std::max(1, std::min(linearSolver.get<int>("Size of Krylov Subspace", 200), maxIterations));
  const double tolerance = linearSolver.get<double>("Tolerance", 1e-9);
  const std::size_t n = s.map->getNodeNumElements();
  const Teuchos::Comm<int>& comm = *s.map->getComm();
  GmresOperators op;
  op.apply = J;
  if (!s.prec.is_null())
    op.precondition = [&s](const double* in, double* out) {
      Teuchos::RCP<MV> X = wrap(s.map, in), Y = wrap(s.map, out);
      s.prec->apply(*X, *Y);
    };
  op.sum = [&comm](const double* in, double* out, int count) {
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, count, in, out);
  };
  // |r| / |r0| with r0 = rhs (dx starts at 0): the forcing term of the inexact Newton step, unpreconditioned
  // because the preconditioner sits on the right (as Belos' "Norm of Initial Residual" scaling had it).
  const GmresResult g = gmres(op, rhs, dx, n, tolerance, maxIterations, krylov, linearResidual);
  KrylovOutcome out;
  out.converged = g.converged;
  out.failed = g.failed;
  out.iterations = g.iterations;
  if (s.work) s.work->krylovIterations += out.iterations;
  return out;
}

}  // namespace pf
