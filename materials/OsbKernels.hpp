#pragma once
// Plain bond loops of the linear ordinary state-based solid (see OsbConstants.hpp for the equations).
// They stream the CSR bond arrays once per pass and allocate nothing; materials compose them.
#include "BondFamily.hpp"
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

// Upper bound of sum_j |dF_i/du_j| of the elastic force for owned i in [begin, end), from the two
// terms of t (direct extension and dilatation coupling), both ends of each bond counted.
void osbStiffnessBound(const FamilyView& fam, const OsbConstants& c, double* bound);

// Directional derivative of osbElasticForce at y along dy (exact, large rotations included):
// d(t M) = dt M + t (I - M M^T) dY / |Y|, dt from de = M . dY and d theta.
void osbElasticForceDerivative(const FamilyView& fam, const OsbConstants& c, const double* y, const double* dy,
                               double* dforce);

// c_b = B omega_b / m_i: stiffness of the deviatoric/extension term of t per unit extension.
void osbPairStiffness(const FamilyView& fam, const OsbConstants& c, double* stiffness);

// Building blocks of the bond loops, shared by the elastic and the J2 kernels so that both do the same
// arithmetic (an elastic J2 point gives exactly the "Elastic" force). A node's family is first gathered
// into a per-node scratch (bond vectors, deformed lengths, neighbour volumes: ~7 kB for 120 bonds, so it
// stays in L1) and every later loop of that node runs on contiguous arrays: one sqrt per bond and step,
// loops the compiler vectorizes, no allocation or virtual call per bond.
namespace osb {

struct FamilyScratch {
  double *d0 = nullptr, *d1 = nullptr, *d2 = nullptr;  // y_j - y_i
  double *len = nullptr;                               // |y_j - y_i|
  double *vj = nullptr;                                // V_j
  double *a = nullptr, *b = nullptr;                   // per-bond work arrays of the caller
};

// Thread-local scratch for families of up to the largest family of [fam.begin, fam.end); grown, never
// shrunk (one allocation per thread and size, not per call).
FamilyScratch& familyScratch(const FamilyView& fam);

// Gathers node i's family into the scratch; returns its size.
int gatherFamily(const FamilyView& fam, const double* y, int i, FamilyScratch& s);

// sum_k omega_k x_k (len_k - x_k - ep_k) V_k over the family (ep null: no plastic extension), in four
// interleaved partial sums (a fixed order, so the result depends only on the family's bond order).
double dilatationSum(const double* w, const double* x, const double* len, const double* ep, const double* vj,
                     int n);

// With s[k] = t_k / len_k (the scalar force state over the deformed length) in the scratch: f_i += t V_j
// along each bond, f_j -= t V_i.
void addBondForces(const FamilyView& fam, int i, const FamilyScratch& sc, const double* s, double* force);

}  // namespace osb

}  // namespace pf
