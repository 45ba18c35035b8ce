#pragma once
// What a Communicator is made of, for src/parallel and the Trilinos adapters (the NOX solver) only: the MPI
// communicator, from which Tpetra's Teuchos::MpiComm is made where one is needed.
#include <mpi.h>

#include "parallel/Communicator.hpp"

namespace pf {

struct Communicator::Impl {
  explicit Impl(MPI_Comm c) : mpi(c) {
    MPI_Comm_rank(c, &rank);
    MPI_Comm_size(c, &size);
  }
  MPI_Comm mpi;
  int rank = 0, size = 1;
};

}  // namespace pf
