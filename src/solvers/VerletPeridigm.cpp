#include "VerletPeridigm.hpp"

#include "model/Model.hpp"

namespace pf {

// Peridigm.cpp: `yPtr[i] = xPtr[i] + uPtr[i] + dt*vPtr[i]`, evaluated left to right, before `u += dt v`.
void peridigmPositions(const double* x, const double* uStart, const double* v, double dt, std::size_t n, double* y) {
  for (std::size_t k = 0; k < n; ++k) y[k] = (x[k] + uStart[k]) + dt * v[k];
}

void verletPositions(const Model& model, const std::vector<double>& uStart, const std::vector<double>& u,
                     const std::vector<double>& v, double dt, std::vector<double>& y) {
  const std::vector<double>& x = model.coordinates();  // overlap order: the owned points first
  y.resize(u.size());
  if (dt == 0.0 || !model.rigidWalls().empty())
    for (std::size_t k = 0; k < u.size(); ++k) y[k] = x[k] + u[k];
  else
    peridigmPositions(x.data(), uStart.data(), v.data(), dt, u.size(), y.data());
}

void halfKickPrescribed(const std::vector<char>& fixed, const std::vector<double>& rho, const std::vector<double>& f,
                        const std::vector<double>& b, double dt, std::vector<double>& v) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (fixed[k]) v[k] += 0.5 * dt * ((f[k] + b[k]) / rho[k / 3]);
}

}  // namespace pf
