#include "KokkosRuntime.hpp"

#include <Kokkos_Core.hpp>

#include <cstdlib>

namespace pf {

void ensureKokkos() {
  if (Kokkos::is_initialized()) return;
  Kokkos::initialize();
  std::atexit([] {
    if (Kokkos::is_initialized()) Kokkos::finalize();
  });
}

}  // namespace pf
