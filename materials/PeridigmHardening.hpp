#pragma once
// Peridigm's isotropic hardening law of "Elastic Plastic Hardening" (Peridigm elastic_plastic_hardening.cxx):
// yield when |t^d|^2/2 - psi0 - H lambda > 0, t^d_n+1 = t^d_tr / (1 + alpha dlambda), dlambda the smallest
// positive root of Peridigm's cubic, solved in closed form as Peridigm solves it. Plain scalars, no throw.
namespace pf {

// dlambda >= 0 of one node: the smallest positive root of
//   |t^d_tr|^2 / (2 (1 + alpha dl)^2) = psi0 + H (lambdaN + dl)          (consistency at n+1)
// written as Peridigm's monic cubic dl^3 + a dl^2 + b dl + c = 0 (updateDeltaLambda): trigonometric roots
// when R^2 < Q^3, Cardano otherwise, 0 when no root is positive. tdNorm = |t^d_tr| (sum over the family with
// V_j), psi0 = Peridigm's pointwise yield value, alpha = s 15 mu / m, H = Peridigm's Hardening Modulus.
// H = 0 (where Peridigm divides by zero) gives the limit, Peridigm's perfectly plastic
// dl = (tdNorm / sqrt(2 psi0) - 1) / alpha (elastic_plastic.cxx).
double peridigmDeltaLambda(double tdNorm, double lambdaN, double psi0, double alpha, double H);

}  // namespace pf
