// GhostTransfers on Epetra block maps (one map, Import and Export per width). To be removed with Epetra (issue 20).
#include <Epetra_BlockMap.h>
#include <Epetra_Export.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>

#include <map>
#include <numeric>
#include <stdexcept>

#include "parallel/CommunicatorImpl.hpp"
#include "parallel/GhostTransfers.hpp"

namespace pf {

namespace {

class EpetraTransfers final : public GhostTransfers {
 public:
  EpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids, int numGlobal)
      : comm_(comm), numOwned_(numOwned), gids_(gids), numGlobal_(numGlobal) {
    width(1), width(3);  // the common widths up front (every rank builds them in the constructor)
  }

  void importToOverlap(const double* owned, double* overlap, int ncomp) const override {
    const Width& w = width(ncomp);
    Epetra_Vector src(View, *w.owned, const_cast<double*>(owned));
    Epetra_Vector dst(View, *w.overlap, overlap);
    if (dst.Import(src, *w.import, Insert) != 0) throw std::runtime_error("Epetra Import to ghosts failed");
  }

  void exportAdd(const double* overlap, double* owned, int ncomp) const override {
    const Width& w = width(ncomp);
    if (!w.exporter) w.exporter.reset(new Epetra_Export(*w.overlap, *w.owned));
    Epetra_Vector src(View, *w.overlap, const_cast<double*>(overlap));
    Epetra_Vector dst(View, *w.owned, owned);
    dst.PutScalar(0.0);
    if (dst.Export(src, *w.exporter, Add) != 0) throw std::runtime_error("Epetra Export from ghosts failed");
  }

  std::vector<double> gatherToRoot(const double* owned, int ncomp) const override {
    const Width& w = width(ncomp);
    if (!w.rootImport) {
      std::vector<int> all(comm_.rank() == 0 ? numGlobal_ : 0);
      std::iota(all.begin(), all.end(), 0);
      w.root.reset(new Epetra_BlockMap(-1, static_cast<int>(all.size()), all.data(), ncomp, 0, comm_.impl().epetra));
      w.rootImport.reset(new Epetra_Import(*w.root, *w.owned));
    }
    std::vector<double> out(comm_.rank() == 0 ? static_cast<std::size_t>(ncomp) * numGlobal_ : 0);
    Epetra_Vector src(View, *w.owned, const_cast<double*>(owned));
    Epetra_Vector dst(View, *w.root, out.data());
    if (dst.Import(src, *w.rootImport, Insert) != 0) throw std::runtime_error("Epetra gather to rank 0 failed");
    return out;
  }

 private:
  struct Width {
    std::unique_ptr<Epetra_BlockMap> owned, overlap;
    std::unique_ptr<Epetra_Import> import;
    mutable std::unique_ptr<Epetra_Export> exporter;
    mutable std::unique_ptr<Epetra_BlockMap> root;
    mutable std::unique_ptr<Epetra_Import> rootImport;
  };
  const Width& width(int ncomp) const {
    Width& w = widths_[ncomp];
    if (!w.import) {  // every rank asks for the same width at the same call: the construction is collective
      const Epetra_MpiComm& ecomm = comm_.impl().epetra;
      const int nOverlap = static_cast<int>(gids_.size());
      w.owned.reset(new Epetra_BlockMap(-1, numOwned_, gids_.data(), ncomp, 0, ecomm));
      w.overlap.reset(new Epetra_BlockMap(-1, nOverlap, gids_.data(), ncomp, 0, ecomm));
      w.import.reset(new Epetra_Import(*w.overlap, *w.owned));
    }
    return w;
  }
  Communicator comm_;
  int numOwned_;
  std::vector<int> gids_;
  int numGlobal_;
  mutable std::map<int, Width> widths_;
};

}  // namespace

std::unique_ptr<GhostTransfers> makeEpetraTransfers(const Communicator& comm, int numOwned, const std::vector<int>& gids,
                                                    int numGlobal) {
  return std::make_unique<EpetraTransfers>(comm, numOwned, gids, numGlobal);
}

}  // namespace pf
