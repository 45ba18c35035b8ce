#pragma once
// A Jacobi-preconditioned BiCGStab for a linear operator on one value per owned node (a scalar field's solve;
// the displacement's Krylov solves go through Tpetra, KrylovSolver.hpp). Dot products are summed over ranks by
// the given reduction, so every rank takes the same branch.
#include <functional>
#include <vector>

namespace pf {

struct ScalarKrylovResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // |b - A x| at the end
};

// Solves A x = b from x = 0 to |b - A x| <= tol |b| (or |b| = 0). apply(x, y): y = A x; inverseDiagonal: the
// Jacobi preconditioner (1 / A_ii); sum: the global sum of a local value. Collective through `sum`.
ScalarKrylovResult bicgstab(const std::function<void(const double*, double*)>& apply,
                            const std::vector<double>& inverseDiagonal, const std::vector<double>& b,
                            std::vector<double>& x, double tol, int maxIterations,
                            const std::function<double(double)>& sum);

}  // namespace pf
