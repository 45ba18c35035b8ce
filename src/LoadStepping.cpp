#include "LoadStepping.hpp"

#include <cmath>

#include "Model.hpp"

namespace pf {

ResidualNorms residualNorms(const Model& model, const std::vector<double>& f, const std::vector<double>& b) {
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double>& V = model.volume();
  double r2 = 0, rd2 = 0, l2 = 0, b2 = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double vol = V[k / 3];
    if (fixed[k]) {
      l2 += f[k] * f[k] * vol * vol;
    } else {
      const double r = f[k] + b[k];
      r2 += r * r * vol * vol;
      rd2 += r * r;
    }
    b2 += b[k] * b[k] * vol * vol;
  }
  double in[4] = {r2, l2, b2, rd2}, out[4];
  model.layout().comm().SumAll(in, out, 4);
  return {std::sqrt(out[0]), std::sqrt(out[1]) + std::sqrt(out[2]), std::sqrt(out[3])};
}

void predictStep(const Model& model, double t, std::vector<double>& u, const std::vector<double>& duPrev) {
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double> before(u);
  model.applyPrescribed(t, u.data());
  double in[2] = {0, 0}, out[2];
  for (std::size_t k = 0; k < u.size(); ++k)
    if (fixed[k]) {
      in[0] += (u[k] - before[k]) * duPrev[k];
      in[1] += duPrev[k] * duPrev[k];
    }
  model.layout().comm().SumAll(in, out, 2);
  const double alpha = out[1] > 0 ? out[0] / out[1] : 0.0;
  for (std::size_t k = 0; k < u.size(); ++k)
    if (!fixed[k]) u[k] += alpha * duPrev[k];
}

}  // namespace pf
