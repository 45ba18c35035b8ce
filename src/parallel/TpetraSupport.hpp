#pragma once
// What the two Tpetra adapters (the ghost transfers and the NOX adapter's Krylov solve) share: Kokkos started
// before the first Tpetra object (and finalised at exit, after main's scope), Tpetra's communicator on the
// run's ranks, and Tpetra vectors that are views of the caller's arrays.
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "parallel/Communicator.hpp"

namespace pf {

void ensureKokkos();

// A Teuchos::MpiComm on the communicator's ranks (no duplicate of the MPI communicator).
Teuchos::RCP<const Teuchos::Comm<int>> teuchosComm(const Communicator& comm);

// A Tpetra (multi)vector V of one column on the caller's array, no copy: an unmanaged host view in both halves
// of the dual view (the Serial node's device memory is host memory, so Tpetra's syncs copy nothing).
template <class V, class MapPtr>
V hostView(const MapPtr& map, const double* data) {
  const std::size_t n = map->getNodeNumElements();
  typename V::dual_view_type::t_dev d(const_cast<double*>(data), n, 1);
  typename V::dual_view_type::t_host h(const_cast<double*>(data), n, 1);
  return V(map, typename V::dual_view_type(d, h));
}

}  // namespace pf
