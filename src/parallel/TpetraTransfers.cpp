// GhostTransfers on Tpetra (issue 20): one point map per width, each point's ncomp values as global entries
// ncomp * gid + c, with an Import (owned to overlap, rank 0) and an Export (overlap to owned) per width. The
// vectors are views of the caller's arrays (wrap), so nothing is copied beyond what the transfer moves.
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include <map>

#include "parallel/GhostTransfers.hpp"
#include "parallel/TpetraSupport.hpp"

namespace pf {

namespace {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using Vec = Tpetra::Vector<double>;

Teuchos::RCP<const Map> pointMap(const std::vector<int>& gids, std::size_t count, int ncomp,
                                 const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  std::vector<GO> entries(count * ncomp);
  for (std::size_t p = 0; p < count; ++p)
    for (int c = 0; c < ncomp; ++c) entries[p * ncomp + c] = static_cast<GO>(gids[p]) * ncomp + c;
  const Tpetra::global_size_t any = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return Teuchos::rcp(new Map(any, Teuchos::ArrayView<const GO>(entries.data(), entries.size()), 0, comm));
}

Vec wrap(const Teuchos::RCP<const Map>& map, const double* data) { return hostView<Vec>(map, data); }

class TpetraTransfers final : public GhostTransfers {
 public:
  TpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids, int numGlobal)
      : numOwned_(numOwned), gids_(gids), numGlobal_(numGlobal), rank_(comm.rank()) {
    ensureKokkos();
    comm_ = teuchosComm(comm);
    width(1), width(3);  // the common widths up front (every rank builds them in the constructor)
  }

  void importToOverlap(const double* owned, double* overlap, int ncomp) const override {
    const Width& w = width(ncomp);
    Vec dst = wrap(w.overlap, overlap);
    dst.doImport(wrap(w.owned, owned), *w.import, Tpetra::INSERT);
  }

  void exportAdd(const double* overlap, double* owned, int ncomp) const override {
    const Width& w = width(ncomp);
    if (w.exporter.is_null()) w.exporter = Teuchos::rcp(new Tpetra::Export<>(w.overlap, w.owned));
    Vec dst = wrap(w.owned, owned);
    dst.putScalar(0.0);
    dst.doExport(wrap(w.overlap, overlap), *w.exporter, Tpetra::ADD);
  }

  std::vector<double> gatherToRoot(const double* owned, int ncomp) const override {
    const Width& w = width(ncomp);
    if (w.rootImport.is_null()) {
      std::vector<int> all(rank_ == 0 ? numGlobal_ : 0);
      for (int p = 0; p < static_cast<int>(all.size()); ++p) all[p] = p;
      w.root = pointMap(all, all.size(), ncomp, comm_);
      w.rootImport = Teuchos::rcp(new Tpetra::Import<>(w.owned, w.root));
    }
    std::vector<double> out(rank_ == 0 ? static_cast<std::size_t>(ncomp) * numGlobal_ : 0);
    Vec dst = wrap(w.root, out.data());
    dst.doImport(wrap(w.owned, owned), *w.rootImport, Tpetra::INSERT);
    return out;
  }

 private:
  struct Width {
    Teuchos::RCP<const Map> owned, overlap;
    Teuchos::RCP<const Tpetra::Import<>> import;
    mutable Teuchos::RCP<const Tpetra::Export<>> exporter;
    mutable Teuchos::RCP<const Map> root;
    mutable Teuchos::RCP<const Tpetra::Import<>> rootImport;
  };
  const Width& width(int ncomp) const {
    Width& w = widths_[ncomp];
    if (w.import.is_null()) {  // every rank asks for the same width at the same call: the construction is collective
      w.owned = pointMap(gids_, static_cast<std::size_t>(numOwned_), ncomp, comm_);
      w.overlap = pointMap(gids_, gids_.size(), ncomp, comm_);
      w.import = Teuchos::rcp(new Tpetra::Import<>(w.owned, w.overlap));
    }
    return w;
  }
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int numOwned_;
  std::vector<int> gids_;
  int numGlobal_, rank_;
  mutable std::map<int, Width> widths_;
};

}  // namespace

std::unique_ptr<GhostTransfers> makeTpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                    int numGlobal) {
  return std::make_unique<TpetraTransfers>(comm, numOwned, gids, numGlobal);
}

}  // namespace pf
