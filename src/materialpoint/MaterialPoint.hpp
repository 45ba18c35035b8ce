#pragma once
// One interior material point with its complete family on a regular lattice (cube in 3D, square in 2D,
// spacing dx, horizon ratio*dx): impose y = F X on every point, evaluate the model on the centre node only
// and read its state. For verification tests and the periforge-point driver; not used by the solver.
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/BondFamily.hpp"
#include "core/InfluenceFunction.hpp"
#include "core/Material.hpp"
#include "core/StateStore.hpp"

namespace pf {

// Builds a registered model from plain values, checked against its ParameterSpecs as a deck's would be
// (unknown or missing parameters, ranges, choices; defaults filled in); throws InputError otherwise.
std::unique_ptr<Material> makeMaterial(const std::string& model, const std::map<std::string, double>& values,
                                       const std::map<std::string, std::string>& strings = {});

class MaterialPoint {
 public:
  // thickness: out-of-plane thickness of the nodal volumes of a 2D model (ignored in 3D); partialVolume:
  // weight the bonds by the share of their cell inside the horizon (PartialVolume.hpp); influence: omega
  // of each bond, evaluated as the solver's layout does (at min(|xi|, delta) with partial volumes).
  MaterialPoint(const Material& mat, double dx, double ratio, double thickness = 0.0, bool partialVolume = false,
                const Influence& influence = Influence(Influence::One));

  void deform(const std::array<double, 9>& F);  // y = F X, F row-major
  void evaluate();                              // trial state of the centre (may throw ConstitutiveFailure)
  void setTime(double t) { view_.time = t; }     // the time evaluate() hands the model (start time: 0)
  // FamilyView::admitted (per node, centre first; null: every point may yield), for loading-balance tests.
  void setAdmitted(const char* admitted) { view_.admitted = admitted; }
  void commit() { state_.commit(); }
  void rollback() { state_.rollback(); }

  double value(const std::string& field) const;  // trial value of a node field at the centre
  // Force-state stress of the centre, sum_j T<xi_j> (x) xi_j V_j (row-major), from the last evaluate().
  std::array<double, 9> stress() const;
  const std::vector<double>& force() const { return force_; }  // 3 per lattice point, centre first
  int numBonds() const { return static_cast<int>(family_.numBonds()); }
  const FamilyView& view() const { return view_; }  // the centre's family (tests compute lattice sums on it)
  double nodeVolume() const { return volume_[0]; }
  double weightedVolume() const { return m_[0]; }
  StateStore& state() { return state_; }

 private:
  const Material& mat_;
  std::vector<double> x_, y_, volume_, force_, m_;
  BondFamily family_;
  FamilyView view_;
  StateStore state_;
};

}  // namespace pf
