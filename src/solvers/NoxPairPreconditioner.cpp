#include "NoxPairPreconditioner.hpp"

#include <Ifpack.h>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "Solver.hpp"
#include "model/Model.hpp"

namespace pf {

// The preconditioner matrix: each bond's extension stiffness c V_j n n^T between its two nodes (the
// reverse bond's c taken as c m_i/m_j), plus the shift on free diagonals, prescribed rows replaced by s.
Teuchos::RCP<Epetra_CrsMatrix> pairMatrix(const Model& model, const Epetra_Map& map, double radiusFactor,
                                          const std::vector<double>* shift, double* scaleOut) {
  const DistributedLayout& L = model.layout();
  const BondFamily& fam = L.family();
  const std::vector<int>& gid = L.gids();
  const std::vector<double>& x = model.coordinates();
  const std::vector<double>& V = model.volume();
  const std::vector<double>& m = model.weightedVolume();
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double> c = model.pairStiffness();
  // Which bonds the matrix keeps, and one global stiffening factor so that the kept bonds carry the
  // second moment sum(k r^2) of all bonds: the smooth modes, which the Krylov solve needs the
  // preconditioner for, see the same stiffness.
  std::vector<char> keep(fam.neighbors.size(), 1);
  double boost = 1.0;
  {
    double moment[2] = {0, 0}, total[2];
    for (int i = 0; i < model.numOwned(); ++i) {
      double shortest = std::numeric_limits<double>::max();
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) shortest = std::min(shortest, fam.refLength[b]);
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
        const double r = fam.refLength[b], kr2 = c[b] * V[fam.neighbors[b]] * r * r;
        keep[b] = r <= radiusFactor * shortest * (1 + 1e-9);
        moment[0] += kr2;
        if (keep[b]) moment[1] += kr2;
      }
    }
    L.comm().sum(moment, total, 2);
    boost = total[1] > 0 ? total[0] / total[1] : 1.0;
  }
  auto A = Teuchos::rcp(new Epetra_CrsMatrix(Copy, map, 0));
  std::vector<int> cols;
  std::vector<double> vals;
  double diagTotal = 0;
  int diagCount = 0;
  for (int i = 0; i < model.numOwned(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const int row = 3 * gid[i] + a;
      cols.assign({3 * gid[i], 3 * gid[i] + 1, 3 * gid[i] + 2});
      vals.assign(3, 0.0);
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
        if (!keep[b]) continue;
        const int j = fam.neighbors[b];
        double n[3];
        for (int d = 0; d < 3; ++d) n[d] = (x[3 * j + d] - x[3 * i + d]) / fam.refLength[b];
        const double k = boost * c[b] * (1.0 + m[i] / m[j]) * V[j];
        for (int d = 0; d < 3; ++d) {
          if (n[a] * n[d] == 0.0) continue;  // planar bonds: no z coupling; storing zeros doubled the work
          vals[d] += k * n[a] * n[d];
          cols.push_back(3 * gid[j] + d);
          vals.push_back(-k * n[a] * n[d]);
        }
      }
      if (!fixed[3 * i + a]) {
        if (shift) vals[a] += (*shift)[3 * i + a];
        diagTotal += vals[a];
        ++diagCount;
      }
      A->InsertGlobalValues(row, static_cast<int>(cols.size()), vals.data(), cols.data());
    }
  }
  double in[2] = {diagTotal, static_cast<double>(diagCount)}, out[2];
  L.comm().sum(in, out, 2);
  const double s = out[1] > 0 ? out[0] / out[1] : 1.0;
  A->FillComplete();
  // Prescribed rows: s on the diagonal, nothing else (the constraint x = xbar decouples them).
  for (int i = 0; i < model.numOwned(); ++i)
    for (int a = 0; a < 3; ++a) {
      if (!fixed[3 * i + a]) continue;
      int len = 0;
      double* rv = nullptr;
      int* ri = nullptr;
      A->ExtractMyRowView(3 * i + a, len, rv, ri);
      for (int e = 0; e < len; ++e) rv[e] = A->GCID(ri[e]) == 3 * gid[i] + a ? s : 0.0;
    }
  *scaleOut = s;
  return A;
}

Teuchos::RCP<Epetra_Operator> factorIfpack(const Teuchos::RCP<Epetra_CrsMatrix>& A, const std::string& type,
                                           int overlap, Teuchos::ParameterList& params) {
  Ifpack factory;
  Teuchos::RCP<Ifpack_Preconditioner> p = Teuchos::rcp(factory.Create(type, A.get(), overlap));
  if (p.is_null()) throw SolverFailure("Newton-Krylov: Ifpack has no preconditioner '" + type + "'");
  if (p->SetParameters(params) != 0 || p->Initialize() != 0 || p->Compute() != 0)
    throw SolverFailure("Newton-Krylov: the Ifpack '" + type + "' factorisation of the pair stiffness failed");
  return p;
}

Teuchos::RCP<Epetra_Operator> buildMl(const Teuchos::RCP<Epetra_CrsMatrix>& A, const Teuchos::ParameterList& user) {
  Teuchos::ParameterList p;
  ML_Epetra::SetDefaults("SA", p);
  p.set("PDE equations", 3);
  p.set("ML output", 0);
  p.set("smoother: type", "symmetric Gauss-Seidel");
  p.set("smoother: sweeps", 1);  // measured: 1 sweep costs 1 more Krylov iteration and saves 30 % of the time
  p.set("coarse: max size", 500);
  p.setParameters(user);
  auto ml = Teuchos::rcp(new ML_Epetra::MultiLevelPreconditioner(*A, p, true));
  return ml;
}

}  // namespace pf
