#pragma once
// Per-node return mapping of the OSB J2 solid with linear isotropic (K) and kinematic (H) hardening
// (Pirzadeh et al. 2024 §3.2, Eqs. 39-57): trial moments, committed node state and constants in; dlambda,
// the scaling of each part of t^d and the updated state out. No bonds, allocation or throw (a failure is a status).
#include "core/Dimension.hpp"

namespace pf {

// Constants of the yield surface written with the weighted volume my (see YieldNormalization):
// psi0 = Cy sigma_bar^2 (Eqs. 39/46), |d eps_p| = dlambda sqrt(Ce psi) (Eq. 55 with the 2D term),
// psi = |t|^2/2 + a2 (t.x)^2 (Eq. 31).
struct OsbYieldConstants {
  double Cy, Ce, a2;
};

inline OsbYieldConstants osbYieldConstants(Dimension dim, double my) {
  if (dim == Dimension::ThreeD) return {2.5 / my, 10.0 / my, 0.0};
  // 2D: psi0 = 8 sigma^2/(3 pi h delta^4) = 4 sigma^2/(3 m) as printed. The (t.x)^2 coefficient that
  // reproduces 3D J2 in plane strain and plane stress with c = 5/12 resp. 1/3 + kappa/(8 mu) is
  // 5/(2m), not the printed 4/(pi h delta^4) = 2/m; Ce follows from |de_p|^2 = dlambda^2 8 psi/m.
  return {4.0 / (3.0 * my), 16.0 / (3.0 * my), 2.5 / my};
}

// Moments over the family (sum_j (.) V_j) of the trial deviatoric force state t^d (Eqs. 31, 40-41).
struct OsbTrialMoments {
  double S2;  // |t^d|^2 (P1 of Eq. 50)
  double Sx;  // t^d . x
  double S3;  // sum (t^d)^3 V: its sign is the sign of sigma_vm (PD analogue of J3)
  double A3;  // sum |t^d| (t^d)^2 V: the scale S3 is compared with
  double Xx;  // x . x
  // sum t^d_tr e^dp_n V: the trial state against the committed plastic extension, whose sign is the sign of
  // sigma_vm under OsbJ2SignRule::PlasticExtension (0 for a node that has not flowed)
  double Se = 0.0;
  // The split along omega x (OsbJ2Constants::omegaSplit, OsbJ2OmegaSplit.hpp; unset otherwise): sum omega x t^d V,
  // m = sum omega x^2 V, sum omega^2 x^2 V
  double Swx = 0.0, Xw = 0.0, Xw2 = 0.0;
};

// History of a node: committed (n) on input, updated (n+1) on output.
struct OsbJ2NodeState {
  double lambda;  // accumulated dlambda
  double alpha;   // equivalent plastic strain (Eq. 57)
  double q;       // scalar back stress (Eq. 56)
  double sign;    // sign of sigma_vm by the third moment: +1/-1, 0 = never set (taken as +1)
};

// The sign that orients sigma_vm against q in the return (docs/materials.md, "Sign of sigma_vm"). OsbJ2NodeState::sign
// stays the third-moment sign whatever the rule (the output's Signed_Von_Mises_Stress).
enum class OsbJ2SignRule {
  // The paper's: the sign of the trial state's third moment S3.
  ThirdMoment,
  // S3's sign as committed at the end of the last step once the node has a back stress (q_n != 0), so that a flip of
  // S3 acts from the next step on. Why: with q != 0 the yield function jumps by 2|q| where S3 changes sign, so the
  // force is not continuous in the displacement within a step and Newton (and ADR) can fail to settle beside such a
  // node; on the material-point cycles and the plates the results are unchanged to the quoted digits.
  CommittedThirdMoment,
  // From the committed plastic extension (OsbTrialMoments::Se), so that q is measured along e^dp, the direction of a
  // Prager back stress. S3 vanishes in pure shear and, in plane strain, in all plastic flow (sigma_zz -> the mean
  // stress), where the paper's sign is arbitrary.
  PlasticExtension,
};

struct OsbJ2Constants {
  OsbYieldConstants yield;  // of the node's normalisation volume
  double bm;                // B/m_i = -B of Eq. 48 (B = 15 mu or 8 mu)
  double g2;                // x-component of t^d decays as 1/(1 + g2 bm dlambda), the rest as Eq. 47
  double yieldStress, isoHardening, kinHardening;  // sigma_y0, K, H
  bool peridigmLaw;         // Peridigm's hardening law with H = peridigmH (PeridigmHardening.hpp); K, H unused
  double peridigmH;
  double tolerance;         // on Eq. 50 written as sigma_vm - sigma_bar, relative to sigma_vm,tr
  int maxIterations;        // Newton updates
  OsbJ2SignRule signRule = OsbJ2SignRule::ThirdMoment;  // orients sigma_vm against q in the return
  // Plane stress with a non-unit influence function: split t^d along omega x, not x (OsbJ2OmegaSplit.hpp), so that
  // the stored plastic extension gives the returned state (docs/materials.md, limitation iii). Needs Swx, Xw, Xw2.
  bool omegaSplit = false;
};

enum class OsbJ2Status { Ok, BackStressBeyondYield, NotConverged };

struct OsbJ2Return {
  OsbJ2NodeState state;  // n+1 (the committed values if the trial state is elastic)
  double dlambda;        // plastic multiplier increment, 0 if elastic
  double G1, G2;         // t^d_n+1 = G1 t_perp + G2 pp x (Eq. 47 per part), t_perp . x = 0
  double pp;             // t^d_tr . x / x . x
  double plasticStrain;  // |d eps_p| (Eq. 55)
  double vonMises;       // sigma_vm of t^d_n+1 (Eq. 20)
  double vonMisesTrial;  // sigma_vm of t^d_tr
  double yieldLevel;     // sigma_bar_n (Eqs. 39/46)
  int iterations;        // Newton updates (0 if elastic or the first guess already converged)
  OsbJ2Status status;    // not Ok: the other fields are incomplete and must not be stored
};

// Out of line for tests and other callers; the J2 kernel inlines the same body (OsbPlasticKernels.cpp).
OsbJ2Return osbJ2ReturnMapping(const OsbTrialMoments& trial, const OsbJ2NodeState& committed,
                               const OsbJ2Constants& k);

}  // namespace pf
