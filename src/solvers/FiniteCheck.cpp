#include "FiniteCheck.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "Solver.hpp"
#include "model/Model.hpp"

namespace pf {

bool finiteEverywhere(const Model& model, double localNorm) {
  return model.max(std::isfinite(localNorm) ? 0.0 : 1.0) == 0.0;
}

double finiteProbe(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s;
}

namespace {

// 1-based global id of the first owned node with a non-finite component of x, or 0 if none.
int firstNonFiniteNode(const Model& model, const std::vector<double>& x) {
  const std::vector<int>& gids = model.layout().gids();
  int best = 0;
  for (int i = 0; i < model.numOwned(); ++i) {
    const bool bad = !std::isfinite(x[3 * i]) || !std::isfinite(x[3 * i + 1]) || !std::isfinite(x[3 * i + 2]);
    const int id = gids[i] + 1;
    if (bad && (best == 0 || id < best)) best = id;
  }
  return best;
}

}  // namespace

void requireFinite(const Model& model, const CheckPoint& at, const char* what, const std::vector<double>& x,
                   double localNorm) {
  if (finiteEverywhere(model, localNorm)) return;
  // A boundary condition that is not finite at this time is the likeliest cause: name its expression.
  model.requireFiniteLoads(at.time);
  // Smallest id over ranks as a max of -id (the reductions are on doubles; ids are exact below 2^53).
  const int local = firstNonFiniteNode(model, x);
  const double neg = model.max(local > 0 ? -static_cast<double>(local) : -std::numeric_limits<double>::max());
  const int id = neg > -std::numeric_limits<double>::max() ? static_cast<int>(-neg) : 0;
  // The owner contributes the coordinates, the other ranks zeros.
  double c[3] = {0, 0, 0}, g[3];
  const std::vector<int>& gids = model.layout().gids();
  for (int i = 0; i < model.numOwned() && id > 0; ++i)
    if (gids[i] + 1 == id)
      for (int d = 0; d < 3; ++d) c[d] = model.coordinates()[3 * i + d];
  model.layout().comm().sum(c, g, 3);
  char msg[320];
  if (id > 0)
    std::snprintf(msg, sizeof msg, "%s: non-finite %s at step %ld (t = %g) at node %d (%g, %g, %g)", at.solver, what,
                  at.step, at.time, id, g[0], g[1], g[2]);
  else  // the norm overflowed although every value is finite
    std::snprintf(msg, sizeof msg, "%s: non-finite %s norm at step %ld (t = %g)", at.solver, what, at.step, at.time);
  throw SolverFailure(msg);
}

void requireFiniteState(const Model& model, const CheckPoint& at, const std::vector<double>& u,
                        const std::vector<double>& v, const std::vector<double>& f, double localProbe) {
  if (finiteEverywhere(model, localProbe)) return;
  requireFinite(model, at, "displacement", u, finiteProbe(u));
  requireFinite(model, at, "velocity", v, finiteProbe(v));
  requireFinite(model, at, "force", f, finiteProbe(f));
  char msg[200];  // every value finite, but their sum overflowed: a state no result should hold either
  std::snprintf(msg, sizeof msg, "%s: state out of range (|u|, |v| or |f| near 1e308) at step %ld (t = %g)", at.solver,
                at.step, at.time);
  throw SolverFailure(msg);
}

std::string stepText(const CheckPoint& at) {
  char buf[160];
  std::snprintf(buf, sizeof buf, " in %s step %ld (t = %.9g)", at.solver, at.step, at.time);
  return buf;
}

}  // namespace pf
