#pragma once
// The bond-associated correspondence kinematics and force state (Chen & Spencer 2019; Peridigm's
// correspondence.cxx, computeBondLevelUnrotatedRateOfDeformationAndRotationTensor, computeStressIntegral and
// BondAssociatedCorrespondenceMaterial::computeForce), per bond of one owned node. Plain arrays in, no state.
#include "core/BondFamily.hpp"
#include "core/Tensor3.hpp"

namespace pf {

// The bond's deformation gradient: the mean of both ends' node gradients with its component along the bond
// replaced by the bond itself, F_b = Fbar + (Y - Fbar xi) (x) xi / |xi|^2, Fbar = (F_i + F_j)/2. The same map
// takes the rate (Y -> the bond's velocity difference, F -> Fdot). Exact for any affine motion: F_b = F.
Mat3 bondGradient(const Mat3& Fi, const Mat3& Fj, const double* xi, const double* Y);

// The projector I - xi (x) xi / |xi|^2 onto the plane normal to the bond (the stress integral's kernel).
Mat3 normalProjector(const double* xi);

// The force state of a bond with first Piola stress P_b (Peridigm's computeForce):
// T = omega / w0_i P_b xi / |xi|^2 + S_i phi_b, with w0_i = sum omega V_j, the stress integral
// S_i = sum_b omega (1/(2 w0_i) + 1/(2 w0_j)) V_j P_b (I - xi xi / |xi|^2) and phi_b = omega K_i^-1 xi the
// first-order gradient weight. Writes T (3 values).
void bondForceState(const Mat3& P, const Mat3& S, const Mat3& Kinv, const double* xi, double omega, double w0,
                    double* T);

// An upper bound of sum_j |df_i/du_j| per owned node for a bond-associated model whose stress moves with the
// gradient by at most C = max(3K, 2mu) (Material::stiffnessBound): the stress-integral part through the
// first-order weights, 4 C a^2 with a = sum omega |K^-1 xi| V_j, plus the direct part 4 C sum omega V_j / |xi|^2 / w0.
void bondAssociatedStiffnessBound(const FamilyView& fam, double C, double* bound);

}  // namespace pf
