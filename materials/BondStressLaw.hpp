#pragma once
// The stress update a bond-associated correspondence model applies to each bond (and, for its node outputs, to each
// node): tau_n+1 and one scalar history h_n+1 (the equivalent plastic strain; none for the elastic law) from tau_n,
// h_n and the unrotated strain increment de over the step dt. Pointwise: no loops, no state store, no input types.
#include <memory>

#include "DruckerPragerPlasticity.hpp"
#include "FosterViscoplasticity.hpp"
#include "core/Tensor3.hpp"

namespace pf {

class BondStressLaw {
 public:
  virtual ~BondStressLaw() = default;
  // True when the law keeps the scalar history (per bond and per node).
  virtual bool hasHistory() const = 0;
  // tau_n+1; writes h_n+1 (left as h_n by the elastic law). Throws ConstitutiveFailure when a solve fails.
  virtual Mat3 update(const Mat3& tauN, double hN, const Mat3& de, double dt, double& h) const = 0;
};

// Hooke's law on the increment: tau_n + K tr(de) I + 2 mu dev(de).
std::unique_ptr<BondStressLaw> hookeBondLaw(double bulk, double shear);
// Peridigm's J2 radial returns (PeridigmJ2Update.hpp): perfectly plastic at Y, or linear isotropic hardening Y + H eps_p.
std::unique_ptr<BondStressLaw> perfectPlasticBondLaw(double bulk, double shear, double yield);
std::unique_ptr<BondStressLaw> isotropicHardeningBondLaw(double bulk, double shear, double yield, double hardening);
// Foster, Silling & Chen (2010)'s rate-dependent J2 update (FosterViscoplasticity.hpp).
std::unique_ptr<BondStressLaw> fosterBondLaw(double bulk, double shear, const FosterLaw& law);
// Li & Geng's Drucker-Prager update (DruckerPragerPlasticity.hpp); the history is the plastic internal variable xi.
std::unique_ptr<BondStressLaw> druckerPragerBondLaw(double bulk, double shear, const DruckerPragerLaw& law);

}  // namespace pf
