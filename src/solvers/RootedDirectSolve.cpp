#include "RootedDirectSolve.hpp"

#include <Amesos2.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <iostream>

namespace pf {
namespace {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using MV = Tpetra::MultiVector<double>;
using Matrix = Tpetra::CrsMatrix<double>;

class RootedDirectSolve : public Tpetra::Operator<double> {
 public:
  explicit RootedDirectSolve(const Teuchos::RCP<const Matrix>& A) : map_(A->getRowMap()) {
    const auto comm = map_->getComm();
    auto err = Teuchos::getFancyOStream(Teuchos::rcpFromRef(std::cerr));
    rooted_ = Tpetra::Details::computeGatherMap(map_, err);
    gather_ = Teuchos::rcp(new Tpetra::Import<>(map_, rooted_));
    // Every row on rank 0, still on the whole communicator; then a copy on rank 0's own communicator.
    Matrix gathered(rooted_, 0);
    gathered.doImport(*A, *gather_, Tpetra::INSERT);
    gathered.fillComplete(rooted_, rooted_);
    const auto self = comm->split(comm->getRank(), 0);
    if (comm->getRank() != 0) return;
    const auto gids = rooted_->getNodeElementList();
    selfMap_ = Teuchos::rcp(new Map(rooted_->getGlobalNumElements(), gids, rooted_->getIndexBase(), self));
    Teuchos::Array<std::size_t> counts(gids.size());
    for (std::size_t r = 0; r < counts.size(); ++r) counts[r] = gathered.getNumEntriesInLocalRow(r);
    auto local = Teuchos::rcp(new Matrix(selfMap_, counts()));
    Teuchos::Array<GO> columns(gathered.getNodeMaxNumRowEntries());
    Teuchos::Array<double> values(columns.size());
    for (std::size_t r = 0; r < counts.size(); ++r) {
      std::size_t n = 0;
      gathered.getGlobalRowCopy(gids[r], columns(), values(), n);
      local->insertGlobalValues(gids[r], columns(0, n), values(0, n));
    }
    local->fillComplete();
    x_ = Teuchos::rcp(new MV(selfMap_, 1));
    b_ = Teuchos::rcp(new MV(selfMap_, 1));
    solver_ = Amesos2::create<Matrix, MV>("KLU2", local, x_, b_);
    solver_->symbolicFactorization().numericFactorization();
  }

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }

  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    const std::size_t k = X.getNumVectors();
    MV rootedX(rooted_, k), rootedY(rooted_, k);
    rootedX.doImport(X, *gather_, Tpetra::INSERT);
    if (!solver_.is_null()) {
      for (std::size_t c = 0; c < k; ++c) {
        {
          Teuchos::ArrayRCP<const double> in = rootedX.getData(c);
          Teuchos::ArrayRCP<double> b = b_->getDataNonConst(0);
          std::copy(in.begin(), in.end(), b.begin());
        }
        solver_->solve();
        Teuchos::ArrayRCP<const double> x = x_->getData(0);
        Teuchos::ArrayRCP<double> out = rootedY.getDataNonConst(c);
        std::copy(x.begin(), x.end(), out.begin());
      }
    }
    MV solved(map_, k);
    solved.doExport(rootedY, *gather_, Tpetra::INSERT);
    Y.update(alpha, solved, beta);
  }

 private:
  Teuchos::RCP<const Map> map_, rooted_, selfMap_;
  Teuchos::RCP<Tpetra::Import<>> gather_;
  Teuchos::RCP<MV> x_, b_;  // rank 0: the solver's vectors
  Teuchos::RCP<Amesos2::Solver<Matrix, MV>> solver_;
};

}  // namespace

Teuchos::RCP<Tpetra::Operator<double>> rootedDirectSolve(const Teuchos::RCP<const Matrix>& A) {
  return Teuchos::rcp(new RootedDirectSolve(A));
}

}  // namespace pf
