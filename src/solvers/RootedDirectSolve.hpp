#pragma once
// Y = alpha A^-1 X + beta Y by one sparse LU factorisation (Amesos2's KLU2) of A gathered onto rank 0, on a
// communicator of that rank alone: the direct solve MueLu makes of a hierarchy of one level, done where KLU2 is
// exact. Amesos2 13.2's KLU2 returns a wrong solution whenever its matrix's communicator has more than one rank,
// even with every row on rank 0 (MueLuPreconditioner.cpp). A must be square with domain, range and row maps alike.
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>
#include <Tpetra_Operator.hpp>

namespace pf {

// Collective: gathers A and factorises it.
Teuchos::RCP<Tpetra::Operator<double>> rootedDirectSolve(const Teuchos::RCP<const Tpetra::CrsMatrix<double>>& A);

}  // namespace pf
