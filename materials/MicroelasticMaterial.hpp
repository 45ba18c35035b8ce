#pragma once
// "Microelastic": the bond-based prototype microelastic solid (PMB of Silling & Askari 2005, Eq. 17; bonds
// break only with a Damage Model, core/BondDamage.hpp): pair force density f = c omega s M,
// s = (|Y| - |xi|)/|xi|, M = Y/|Y|, with the micromodulus c set so that an isotropic stretch stores the
// continuum energy (3D: c = 18K/(pi delta^4)).
// 3D and plane strain have nu = 1/4, plane stress nu = 1/3. Declares Stored_Elastic_Energy = V_i W_i.
// With a Thermal Expansion Coefficient alpha it reads Temperature_Change: node i's half of each pair force sees
// the stretch less a dT_i (a = alpha; (1 + nu) alpha in plane strain), so the pair sees the mean of its ends'.
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"

namespace pf {

class MicroelasticMaterial : public Material {
 public:
  explicit MicroelasticMaterial(const MaterialInput& in);
  static MaterialEntry entry();

  std::vector<StateSpec> stateSpecs() const override;
  void computeForce(const FamilyView& fam, const double* y, StateStore& state, double* force) const override;
  void stiffnessBound(const FamilyView& fam, double* bound) const override;
  void pairStiffness(const FamilyView& fam, double* c) const override;
  bool hasForceDerivative() const override { return true; }
  bool forceDerivative(const FamilyView& fam, const double* y, const double* dy, const StateStore& state,
                       double* dforce) const override;
  void enableOutput(const std::string& name) const override;
  bool breaksBonds() const override { return true; }  // every kernel drops broken bonds (BondDamage.hpp)
  std::vector<std::string> fieldsRead() const override;  // Temperature_Change with thermal expansion
  double density() const override { return density_; }
  Dimension dimension() const override { return dim_; }

  double bulkModulus() const { return bulk_; }
  double poissonRatio() const { return dim_ == Dimension::PlaneStress ? 1.0 / 3.0 : 0.25; }
  double youngsModulus() const { return 3.0 * bulk_ * (1.0 - 2.0 * poissonRatio()); }
  // Micromodulus c of owned node i (see the .cpp): 4 W1 / Q, W1 the continuum energy density per unit
  // squared isotropic stretch, Q the continuum moment of |xi| over the horizon, divided by the family's
  // mean influence (1 for omega = 1).
  double micromodulus(const FamilyView& fam, int i) const;

 protected:
  // What Peridigm's Elastic Bond Based (ElasticBondBasedMaterial.hpp) does otherwise; the same kernels.
  struct Calibration {
    const char* thicknessName;  // the planar thickness parameter: "Thickness" / Peridigm's "Height"
    bool peridigmPlanar;        // 2D: 4 W1 = 8K (Peridigm's c = 12K/(pi h delta^3)) instead of the energy match
    bool influence;             // omega from the discretization's Influence Function (false: omega = 1)
  };
  MicroelasticMaterial(const MaterialInput& in, const Calibration& cal);

 private:
  double omega(const FamilyView& fam, int b) const { return influence_ && !fam.unitInfluence ? fam.influence[b] : 1.0; }

  // The loops, mechanics-only (Thermal false: the code as before) or with the thermal stretch.
  template <bool Thermal>
  void forces(const FamilyView& fam, const double* y, StateStore& state, double* force) const;
  template <bool Thermal>
  void derivative(const FamilyView& fam, const double* y, const double* dy, double* dforce) const;

  double thickness_;  // before dim_: dimensionFrom (dim_'s initialiser) writes it
  Dimension dim_;
  double density_, bulk_;
  double fourW1_;          // 4 W1 of micromodulus() (see the .cpp)
  bool influence_ = true;  // Calibration::influence
  double thermal_ = 0.0;  // a of the free thermal stretch a dT (see the .cpp); 0: no thermal expansion
  mutable bool energyWanted_ = false;  // set by enableOutput("Stored_Elastic_Energy") before the run
};

}  // namespace pf
