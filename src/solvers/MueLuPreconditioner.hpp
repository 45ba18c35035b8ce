#pragma once
// MueLu's smoothed aggregation as the preconditioner of the Krylov solve (KrylovSolver.hpp), built from the pair
// stiffness with what MueLu needs besides the matrix: the rigid-body near-null space and the points' coordinates.
// At more than one rank the coarsest level is moved onto one rank before its direct solve (why: the .cpp).
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>
#include <Tpetra_MultiVector_decl.hpp>
#include <Tpetra_Operator.hpp>

namespace pf {

class Model;

// Made from the model when the solver is set up and kept only until the preconditioner is built.
struct MueLuInputs {
  Teuchos::RCP<Tpetra::MultiVector<double>> nullspace;    // rigid-body modes on the dof map
  Teuchos::RCP<Tpetra::MultiVector<double>> coordinates;  // x, y, z on the point map (point id = dof id / 3)
};

// dofMap: the Newton vectors' map, dof id 3 * point + component, three consecutive dofs per owned point.
MueLuInputs mueLuInputs(const Teuchos::RCP<const Tpetra::Map<>>& dofMap, const Model& model);

// Collective. linearSolver: the deck's "Linear Solver" list; its "MueLu" sub-list overrides Periforge's settings.
// MueLu's exceptions pass through (the caller reports them).
Teuchos::RCP<Tpetra::Operator<double>> buildMueLu(const Teuchos::RCP<Tpetra::CrsMatrix<double>>& A,
                                                  const MueLuInputs& inputs, Teuchos::ParameterList& linearSolver);

}  // namespace pf
