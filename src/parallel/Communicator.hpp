#pragma once
// A group of MPI ranks and the reductions the solvers and writers need, with neither mpi.h nor Trilinos in
// sight: above src/parallel, code sees ranks, sums and maxima only. Copies share one communicator. The
// MPI run itself (init/finalize) is an MpiSession, owned by the executable's main.
#include <memory>
#include <string>
#include <vector>

namespace pf {

class Communicator {
 public:
  static Communicator world();  // every rank of the run (MPI must be initialised, see MpiSession)

  int rank() const;
  int size() const;
  // Reductions over all ranks, every rank gets the result (MPI_Allreduce on doubles, as Epetra's
  // SumAll/MaxAll were, so results are bit-identical to the code's before issue 20). in and out must not overlap.
  double sum(double v) const;
  double max(double v) const;
  void sum(const double* in, double* out, int n) const;
  void max(const double* in, double* out, int n) const;
  void barrier() const;
  // Collective: the lowest rank whose `mine` is true, or -1 when it is false on every rank. Lets ranks
  // agree on a failure that happened on some of them only (a rank-0 file write, say).
  int firstFailing(bool mine) const;
  bool anyFailed(bool mine) const { return firstFailing(mine) >= 0; }
  // Collective: rank 0 gets every rank's values concatenated in rank order; the others get an empty vector.
  std::vector<double> gatherToRoot(const std::vector<double>& mine) const;
  // Collective: every rank gets every rank's values concatenated in rank order (few values per rank).
  std::vector<double> allGather(const std::vector<double>& mine) const;
  // Collective: every rank returns root's text (the others' argument is ignored).
  std::string broadcast(const std::string& text, int root) const;

  struct Impl;  // defined in parallel/CommunicatorImpl.hpp (the MPI_Comm, its rank and size)
  const Impl& impl() const;

 private:
  explicit Communicator(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
};

// MPI_Init in the constructor, MPI_Finalize in the destructor: one per process, alive while any
// Communicator is used.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const;  // in the world communicator
};

}  // namespace pf
