#pragma once
// Restarted right-preconditioned GMRES on plain arrays, from x = 0, stopping when the Arnoldi (implicit) residual
// falls to tol |b|. It makes only the operator products and preconditioner applications the iteration needs: one of
// each per iteration (no product for the initial residual of x = 0, none for an explicit residual check, the update
// x = Z y from the kept M⁻¹ v_j), since the Newton step's product costs about a force evaluation.
#include <cstddef>
#include <functional>
#include <vector>

namespace pf {

struct GmresOperators {
  std::function<bool(const double* in, double* out)> apply;           // out = A in; false: the product failed
  std::function<void(const double* in, double* out)> precondition;    // out = M⁻¹ in; empty: the identity
  std::function<void(const double* in, double* out, int n)> sum;      // sums n values over the ranks (collective)
};

struct GmresResult {
  bool converged = false;
  bool failed = false;  // a product failed: x is unusable
  int iterations = 0;
  double relativeResidual = 1.0;  // |b - A x| / |b| by the Arnoldi relation
};

// Solves A x = b (n local entries) with at most maxIterations iterations, restarting every `restart`. residual (or
// null): receives b - A x by the Arnoldi relation (no product), e.g. for A x = b - residual.
GmresResult gmres(const GmresOperators& op, const double* b, double* x, std::size_t n, double tol, int maxIterations,
                  int restart, double* residual = nullptr);

}  // namespace pf
