#include "MueLuPreconditioner.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "RigidBodyModes.hpp"
#include "RootedDirectSolve.hpp"
#include "model/Model.hpp"

namespace pf {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using MV = Tpetra::MultiVector<double>;

MueLuInputs mueLuInputs(const Teuchos::RCP<const Map>& dofMap, const Model& model) {
  const int owned = model.numOwned();
  const std::size_t n = 3 * static_cast<std::size_t>(owned);
  MueLuInputs in;
  const RigidBodyModes modes = rigidBodyModes(model.coordinates(), owned, model.layout().comm());
  in.nullspace = Teuchos::rcp(new MV(dofMap, modes.count));
  for (int k = 0; k < modes.count; ++k) {
    Teuchos::ArrayRCP<double> b = in.nullspace->getDataNonConst(k);
    std::copy(modes.values.begin() + k * n, modes.values.begin() + (k + 1) * n, b.getRawPtr());
  }
  // MueLu amalgamates 3 dofs into a node as dof id / 3 (number of equations 3): the same ids here.
  std::vector<GO> points(owned);
  for (int i = 0; i < owned; ++i) points[i] = dofMap->getGlobalElement(3 * i) / 3;
  const Tpetra::global_size_t any = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto pointMap = Teuchos::rcp(new Map(any, Teuchos::ArrayView<const GO>(points.data(), points.size()), 0,
                                       dofMap->getComm()));
  in.coordinates = Teuchos::rcp(new MV(pointMap, 3));
  const std::vector<double>& x = model.coordinates();
  for (int c = 0; c < 3; ++c) {
    Teuchos::ArrayRCP<double> col = in.coordinates->getDataNonConst(c);
    for (int i = 0; i < owned; ++i) col[i] = x[3 * i + c];
  }
  return in;
}

// ML's settings that Periforge measured (3 dofs per point, one symmetric Gauss-Seidel sweep: one more Krylov
// iteration, 30 % less time) and the rigid-body near-null space (without it MueLu takes the translations alone,
// which an elastic body's aggregates cannot rotate with).
//
// The coarsest level on one rank: MueLu solves its coarsest level with Amesos2's KLU2, the only direct solver
// Debian's Trilinos 13.2 enables, and KLU2 there returns a wrong solution for a matrix spread over more than one
// rank (a 1D Laplacian of 8 rows at np 2: relative error 0.5; the beam's one-level preconditioner: 1.5, against
// 3e-11 at np 1; test/mpi/test_coarse_direct_solve.cpp, docs/benchmark-log.md "MueLu's coarse level at np > 1"). At np 2
// every Krylov solve therefore met a wrong coarse correction (the beam: 1 566 GMRES iterations against 562 at
// np 1). MueLu's repartitioning from level 1 with more rows per rank than the coarsest level can have (`coarse:
// max size`) puts that level on one rank, where KLU2 is exact; a larger level keeps its ranks unless it is
// unbalanced (then zoltan2 splits it by the points' coordinates). One rank: nothing is repartitioned.
Teuchos::RCP<Tpetra::Operator<double>> buildMueLu(const Teuchos::RCP<Tpetra::CrsMatrix<double>>& A,
                                                  const MueLuInputs& inputs, Teuchos::ParameterList& linearSolver) {
  Teuchos::ParameterList p;
  p.set("verbosity", "none");
  p.set("multigrid algorithm", "sa");
  p.set("number of equations", 3);
  p.set("coarse: max size", 500);
  p.set("smoother: type", "RELAXATION");
  p.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  p.sublist("smoother: params").set("relaxation: sweeps", 1);
  p.set("repartition: enable", true);
  p.set("repartition: partitioner", "zoltan2");
  p.set("repartition: start level", 1);
  const Teuchos::ParameterList* user = linearSolver.isSublist("MueLu") ? &linearSolver.sublist("MueLu") : nullptr;
  if (user) p.setParameters(*user);
  if (!user || !user->isParameter("repartition: min rows per proc"))
    p.set("repartition: min rows per proc", std::max(800, p.get<int>("coarse: max size") + 1));
  // One level (no coarser level allowed): MueLu's preconditioner is the direct solve of A by KLU2 alone, which
  // repartitioning cannot move (it starts at level 1); at more than one rank it is made on rank 0 instead.
  const int maxSize = p.get<int>("coarse: max size");
  const std::string coarse = p.isParameter("coarse: type") ? p.get<std::string>("coarse: type") : "KLU2";
  const bool oneLevel = A->getGlobalNumRows() <= static_cast<Tpetra::global_size_t>(std::max(maxSize, 0)) ||
                        (p.isParameter("max levels") && p.get<int>("max levels") <= 1);
  if (oneLevel && A->getComm()->getSize() > 1 && (coarse == "KLU2" || coarse == "KLU" || coarse == "Klu"))
    return rootedDirectSolve(A);
  if (!inputs.nullspace.is_null()) p.sublist("user data").set("Nullspace", inputs.nullspace);
  if (!inputs.coordinates.is_null()) p.sublist("user data").set("Coordinates", inputs.coordinates);
  Teuchos::RCP<Tpetra::Operator<double>> op = A;
  return MueLu::CreateTpetraPreconditioner<double, Map::local_ordinal_type, GO, Map::node_type>(op, p);
}

}  // namespace pf
