#include "TpetraSupport.hpp"

#include <Kokkos_Core.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <cstdlib>

#include "parallel/CommunicatorImpl.hpp"

namespace pf {

void ensureKokkos() {
  if (Kokkos::is_initialized()) return;
  Kokkos::initialize();
  std::atexit([] {
    if (Kokkos::is_initialized()) Kokkos::finalize();
  });
}

Teuchos::RCP<const Teuchos::Comm<int>> teuchosComm(const Communicator& comm) {
  return Teuchos::rcp(new Teuchos::MpiComm<int>(comm.impl().mpi));
}

}  // namespace pf
