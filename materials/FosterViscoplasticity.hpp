#pragma once
// The rate-dependent J2 update of Foster, Silling & Chen (2010), Sections 5-9, on the unrotated Cauchy
// stress: elastic trial (Eqs. 49, 52), flow stress G = Y (1 + eps_p/eps_0)^(1/n) (1 + rate/rate_0)^(1/m)
// (Eqs. 58-59) with the hardening at the step's start and the rate implicit (Eqs. 37, 61), radial return
// (Eq. 50). Scalar functions on plain values; the only throw is ConstitutiveFailure (no convergence).
#include "core/Tensor3.hpp"

namespace pf {

struct FosterLaw {
  double yield;      // Y, quasi-static yield stress
  double n;          // strain hardening exponent
  double m;          // rate sensitivity exponent
  double eps0;       // reference plastic strain
  double rate0;      // reference plastic strain rate
};

// G(eps_p, rate) of Eqs. 58-59.
double fosterFlowStress(const FosterLaw& law, double epsP, double rate);

struct FosterStep {
  Mat3 tau;          // unrotated Cauchy stress at the step's end
  double epsP;       // equivalent plastic strain (Eq. 39: eps_p += sqrt(2/3) dlambda)
  double rate;       // equivalent plastic strain rate sqrt(2/3) dlambda / dt
  int iterations;    // of the scalar solve (0: elastic step)
};

// One step from the committed tauN, epsPn with the unrotated strain increment de over dt, bulk modulus K
// and shear modulus mu. dt <= 0 (no time passed) gives the elastic trial: the dt -> 0 limit of Eq. 60,
// where dlambda = rate dt -> 0. Solves Eq. 60 for dlambda by Newton's method safeguarded by bisection on
// its bracket [0, |S_tr|/(2 mu)]; throws ConstitutiveFailure after 100 iterations without convergence.
FosterStep fosterUpdate(const FosterLaw& law, double K, double mu, const Mat3& tauN, double epsPn, const Mat3& de,
                        double dt);

}  // namespace pf
