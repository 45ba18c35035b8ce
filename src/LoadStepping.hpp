#pragma once
// Pieces shared by the quasi-static solvers (relaxation and Newton): the load-step predictor and the
// residual measures their convergence tests use, so both judge a step the same way.
#include <vector>

namespace pf {

class Model;

struct ResidualNorms {
  double residual = 0;         // || (f + b) V || over free dofs (force)
  double load = 0;             // || f V || over prescribed dofs (reaction) + || b V ||
  double residualDensity = 0;  // || f + b || over free dofs (force density, Peridigm's tolerance unit)
};

// f: internal force density, b: body force density, 3 per owned node; reduced over all ranks.
ResidualNorms residualNorms(const Model& model, const std::vector<double>& f, const std::vector<double>& b);

// Sets the prescribed components of u to their values at t and moves the free ones by the previous
// step's increment scaled by how the prescribed increment continues it (exact for a linear problem
// under proportional loading; after a reversal it extrapolates backwards, as the load does).
void predictStep(const Model& model, double t, std::vector<double>& u, const std::vector<double>& duPrev);

}  // namespace pf
