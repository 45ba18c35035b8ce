#pragma once
// Makes a step that can fail on some ranks only (rank 0's file writes, say) fail on all of them: every
// rank calls collectively(comm, step); if step threw on any rank, every rank throws the lowest failing
// rank's error (same message; InputError and ConstitutiveFailure keep their type, the rest become
// std::runtime_error), so no rank is left waiting in a collective. Costs one MPI_Allreduce per call.
#include <exception>

#include "parallel/Communicator.hpp"

namespace pf {

// Collective: throws on every rank when error is set on any rank (see above); returns otherwise.
void agreeOnFailure(const Communicator& comm, const std::exception_ptr& error);

template <class Step>
void collectively(const Communicator& comm, Step&& step) {
  std::exception_ptr error;
  try {
    step();
  } catch (...) {
    error = std::current_exception();
  }
  agreeOnFailure(comm, error);
}

}  // namespace pf
