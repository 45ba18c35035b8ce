#include "MaterialPoint.hpp"

#include <algorithm>
#include <cmath>

#include "core/InputError.hpp"
#include "core/MaterialEntry.hpp"
#include "discretization/NeighborSearch.hpp"

namespace pf {

std::unique_ptr<Material> makeMaterial(const std::string& model, const std::map<std::string, double>& values,
                                       const std::map<std::string, std::string>& strings) {
  const MaterialEntry* entry = findMaterial(model);
  if (!entry) throw InputError("unknown material model '" + model + "'");
  MaterialInput in;
  in.name = model;
  in.inputFile = "(material point)";
  in.path = "Materials/" + model;
  in.values = values;
  in.strings = strings;
  in.strings["Material Model"] = model;
  applySpecs(entry->parameters, in);  // ranges, choices and defaults, as the input layer does for a deck
  return entry->create(in);
}

MaterialPoint::MaterialPoint(const Material& mat, double dx, double ratio, double thickness, bool partialVolume,
                             const Influence& influence)
    : mat_(mat) {
  const bool planar = isPlanar(mat.dimension());
  const double horizon = ratio * dx;
  // Partial-volume families reach half a cell diagonal (< dx) beyond the horizon.
  const double margin = partialVolume ? dx : 0.5 * dx;
  const int n = static_cast<int>(std::ceil(ratio)) + (partialVolume ? 2 : 1);
  const int nz = planar ? 0 : n;
  x_ = {0.0, 0.0, 0.0};  // the centre is node 0, the only owned node
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -nz; k <= nz; ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        if (std::sqrt(double(i * i + j * j + k * k)) * dx > horizon * (1.0 + 1e-6) + margin) continue;
        x_.push_back(i * dx); x_.push_back(j * dx); x_.push_back(k * dx);
      }
  const int numPoints = static_cast<int>(x_.size() / 3);
  volume_.assign(numPoints, planar ? dx * dx * thickness : dx * dx * dx);
  const std::array<double, 3> cell = {dx, dx, planar ? 0.0 : dx};
  buildFamilies(x_, 1, {horizon}, family_, partialVolume ? &cell : nullptr);
  family_.influence.resize(family_.numBonds());  // omega = 1 (the paper's) unless asked otherwise
  for (std::size_t b = 0; b < family_.numBonds(); ++b)
    family_.influence[b] = influenceValue(influence, std::min(family_.refLength[b], horizon), horizon);
  family_.unitInfluence = influence.kind == Influence::One;
  m_.assign(numPoints, 0.0);
  view_ = makeView(family_, 0, 1, x_.data(), volume_.data(), m_.data(), horizon);
  computeWeightedVolume(view_, m_.data());
  // Only the centre's family is built; on the (infinite) lattice every point has the centre's m, which
  // is what a model reading a neighbour's m (e.g. a stiffness bound) should see.
  const double m0 = m_[0];
  m_.assign(numPoints, m0);
  state_.allocate(mat.stateSpecs(), 1, family_.numBonds());
  y_ = x_;
  force_.assign(x_.size(), 0.0);
}

void MaterialPoint::deform(const std::array<double, 9>& F) {
  for (std::size_t p = 0; p < x_.size(); p += 3)
    for (int a = 0; a < 3; ++a)
      y_[p + a] = F[3 * a] * x_[p] + F[3 * a + 1] * x_[p + 1] + F[3 * a + 2] * x_[p + 2];
}

void MaterialPoint::evaluate() {
  force_.assign(x_.size(), 0.0);
  mat_.computeForce(view_, y_.data(), state_, force_.data());
}

double MaterialPoint::value(const std::string& field) const {
  return const_cast<StateStore&>(state_).trial(field)[0];
}

std::array<double, 9> MaterialPoint::stress() const {
  // Each neighbour j appears once in the centre's family, and receives -T<xi_j> V_0 from it.
  std::array<double, 9> s{};
  for (std::size_t b = 0; b < family_.numBonds(); ++b) {
    const int j = family_.neighbors[b];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        s[3 * a + c] += -force_[3 * j + a] / volume_[0] * (x_[3 * j + c] - x_[c]) * volume_[j];
  }
  return s;
}

}  // namespace pf
