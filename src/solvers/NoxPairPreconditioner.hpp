#pragma once
// Part of the NOX adapter (with NewtonKrylov.cpp; Epetra's stack is allowed here only): the sparse
// pair-stiffness matrix that preconditions the matrix-free Newton-Krylov solve, and its Ifpack or ML
// factorisation.
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Operator.h>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace pf {

class Model;

// Each bond's extension stiffness c V_j n n^T between its two nodes (the reverse bond's c taken as
// c m_i/m_j), bonds longer than radiusFactor x the node's shortest kept out and the rest stiffened to
// the family's second moment; shift (or null, 3 per owned node) is added to the free diagonal (a Newmark
// step's rho / (beta dt^2)); prescribed rows hold *scaleOut (the mean free diagonal) alone.
Teuchos::RCP<Epetra_CrsMatrix> pairMatrix(const Model& model, const Epetra_Map& map, double radiusFactor,
                                          const std::vector<double>* shift, double* scaleOut);

Teuchos::RCP<Epetra_Operator> factorIfpack(const Teuchos::RCP<Epetra_CrsMatrix>& A, const std::string& type,
                                           int overlap, Teuchos::ParameterList& params);

// Smoothed-aggregation AMG with 3 dofs per point; user (a deck's "ML" sub-list) overrides the defaults.
Teuchos::RCP<Epetra_Operator> buildMl(const Teuchos::RCP<Epetra_CrsMatrix>& A, const Teuchos::ParameterList& user);

}  // namespace pf
