#include "FieldSurface.hpp"

namespace pf {

void FieldSurface::addFlux(NodalLoad q, double layer) { terms_.push_back({std::move(q), 0.0, layer}); }

void FieldSurface::addConvection(NodalLoad ambient, double h, double layer) {
  terms_.push_back({std::move(ambient), h, layer});
}

bool FieldSurface::linear() const {
  for (const Term& t : terms_)
    if (t.h > 0.0) return true;
  return false;
}

void FieldSurface::addLinear(const double* T, double* out) const {
  for (const Term& t : terms_)
    for (int i : t.load.nodes) out[i] -= t.h / t.layer * T[i];
}

void FieldSurface::addDiagonal(double* diag) const {
  for (const Term& t : terms_)
    for (int i : t.load.nodes) diag[i] += t.h / t.layer;
}

void FieldSurface::addSource(double time, const std::vector<double>& x, double* out) const {
  for (const Term& t : terms_) {
    const double scale = (t.h > 0.0 ? t.h : 1.0) / t.layer;
    forEachLoadValue(t.load, x, time, 1, [&](int i, double v) { out[i] += scale * v; });
  }
}

}  // namespace pf
