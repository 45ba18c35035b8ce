#include "Communicator.hpp"

#include <utility>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {

// MPI_COMM_WORLD itself, not a duplicate: nothing then has to be freed before MPI_Finalize, and Tpetra's
// communicators made on it address the same ranks.
Communicator Communicator::world() { return Communicator(std::make_shared<const Impl>(MPI_COMM_WORLD)); }

const Communicator::Impl& Communicator::impl() const { return *impl_; }

int Communicator::rank() const { return impl_->rank; }
int Communicator::size() const { return impl_->size; }

double Communicator::sum(double v) const {
  double g = 0;
  sum(&v, &g, 1);
  return g;
}

double Communicator::max(double v) const {
  double g = 0;
  max(&v, &g, 1);
  return g;
}

void Communicator::sum(const double* in, double* out, int n) const {
  MPI_Allreduce(in, out, n, MPI_DOUBLE, MPI_SUM, impl_->mpi);
}

void Communicator::max(const double* in, double* out, int n) const {
  MPI_Allreduce(in, out, n, MPI_DOUBLE, MPI_MAX, impl_->mpi);
}

void Communicator::barrier() const { MPI_Barrier(impl_->mpi); }

int Communicator::firstFailing(bool mine) const {
  const int candidate = mine ? rank() : size();
  int lowest = 0;
  MPI_Allreduce(&candidate, &lowest, 1, MPI_INT, MPI_MIN, impl_->mpi);
  return lowest < size() ? lowest : -1;
}

namespace {

// Where each rank's values start in the concatenation (a gatherv's displacements), and the total last.
std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> displs(counts.size() + 1, 0);
  for (std::size_t r = 0; r < counts.size(); ++r) displs[r + 1] = displs[r] + counts[r];
  return displs;
}

}  // namespace

std::vector<double> Communicator::gatherToRoot(const std::vector<double>& mine) const {
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(rank() == 0 ? size() : 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, impl_->mpi);
  const std::vector<int> displs = displacements(counts);
  std::vector<double> out(static_cast<std::size_t>(displs.back()));
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, out.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, impl_->mpi);
  return out;
}

std::vector<double> Communicator::allGather(const std::vector<double>& mine) const {
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(size());
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, impl_->mpi);
  const std::vector<int> displs = displacements(counts);
  std::vector<double> out(static_cast<std::size_t>(displs.back()));
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, out.data(), counts.data(), displs.data(), MPI_DOUBLE, impl_->mpi);
  return out;
}

std::string Communicator::broadcast(const std::string& text, int root) const {
  int n = static_cast<int>(text.size());
  MPI_Bcast(&n, 1, MPI_INT, root, impl_->mpi);
  std::string out = rank() == root ? text : std::string(static_cast<std::size_t>(n), '\0');
  if (n > 0) MPI_Bcast(&out[0], n, MPI_CHAR, root, impl_->mpi);
  return out;
}

MpiSession::MpiSession(int& argc, char**& argv) { MPI_Init(&argc, &argv); }

MpiSession::~MpiSession() { MPI_Finalize(); }

int MpiSession::rank() const {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

}  // namespace pf
