#pragma once
// Plain bond loops of the linear ordinary state-based solid (see OsbConstants.hpp for the equations).
// They stream the CSR bond arrays once per pass and allocate nothing; materials compose them. The
// shared per-node building blocks are in OsbBondLoops.hpp.
#include "core/BondFamily.hpp"
#include "OsbConstants.hpp"

namespace pf {

// theta_i = k (D/m_i) sum_j omega x (e - e^dp) V_j for owned i in [begin, end). edp may be null (no
// plastic extension). Eq. 4 (elastic) and Eq. 16 (with plastic extension).
void osbDilatation(const FamilyView& fam, const OsbConstants& c, const double* y, const double* edp,
                   double* theta);

// Elastic force state t = A theta omega x/m + B omega (e - c theta x)/m along the deformed bond; adds
// f_i += t V_j M and f_j -= t V_i M (Eqs. 7-13).
void osbElasticForce(const FamilyView& fam, const OsbConstants& c, const double* y, const double* theta,
                     double* force);

// osbDilatation (edp null) and osbElasticForce in one pass over the bonds: t_ij needs only theta_i, so
// each family is gathered once and its force added while it is in L1. Same arithmetic, same results.
void osbElasticDilatationAndForce(const FamilyView& fam, const OsbConstants& c, const double* y, double* theta,
                                  double* force);

// Stored elastic energy V_i W_i of owned i in [begin, end) (Peridigm's Stored_Elastic_Energy, 3D):
//   W_i = kappa theta_i^2 / 2 + s_i (15 mu / (2 m_i)) sum_j omega_ij (e_ij - theta_i |xi_ij| / 3 - e^dp_ij)^2 V_j
// with the bond's partial-volume share of V_j when the family has one; theta as the force evaluation gives it;
// edp: the J2 models' deviatoric plastic extension (null: 0), scf: Peridigm's shear correction factor (null: s = 1);
// dT (Temperature_Change per overlap node, or null): e_ij less the free thermal extension thermal dT_i |xi_ij|, theta
// being the mechanical dilatation the thermal kernels give.
void osbElasticEnergy(const FamilyView& fam, const ElasticModuli& em, const double* y, const double* theta,
                      double* energy, const double* edp = nullptr, const double* scf = nullptr, double thermal = 0.0,
                      const double* dT = nullptr);

// Upper bound of sum_j |dF_i/du_j| of the elastic force for owned i in [begin, end), from the two
// terms of t (direct extension and dilatation coupling), both ends of each bond counted.
void osbStiffnessBound(const FamilyView& fam, const OsbConstants& c, double* bound);

// Directional derivative of osbElasticForce at y along dy (exact, large rotations included):
// d(t M) = dt M + t (I - M M^T) dY / |Y|, dt from de = M . dY and d theta. With dT (Temperature_Change per overlap
// node), that of osbThermoelasticDilatationAndForce with the coefficient `thermal`.
void osbElasticForceDerivative(const FamilyView& fam, const OsbConstants& c, const double* y, const double* dy,
                               double* dforce, double thermal = 0.0, const double* dT = nullptr);

// c_b = B omega_b / m_i: stiffness of the deviatoric/extension term of t per unit extension.
void osbPairStiffness(const FamilyView& fam, const OsbConstants& c, double* stiffness);

}  // namespace pf
