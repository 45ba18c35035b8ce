#pragma once
// What a Communicator is made of, for src/parallel and the Epetra adapters (the NOX solver) only: the
// MPI communicator and an Epetra_MpiComm on it (no duplicate: both address the same ranks and tags).
#include <Epetra_MpiComm.h>
#include <mpi.h>

#include "parallel/Communicator.hpp"

namespace pf {

struct Communicator::Impl {
  explicit Impl(MPI_Comm c) : mpi(c), epetra(c) {}
  MPI_Comm mpi;
  Epetra_MpiComm epetra;
};

}  // namespace pf
