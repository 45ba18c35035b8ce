#pragma once
// Tpetra's vectors are Kokkos views: Kokkos must be up before the first one is made. ensureKokkos starts it on
// first use and registers its finalisation at exit (after main's scope, where every Tpetra object lives).
namespace pf {

void ensureKokkos();

}  // namespace pf
