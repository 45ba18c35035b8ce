#pragma once
// Peridigm's isotropic hardening law of "Elastic Plastic Hardening" (Peridigm elastic_plastic_hardening.cxx):
// yield when |t^d|^2/2 - psi0 - H lambda > 0, t^d_n+1 = t^d_tr / (1 + alpha dlambda), dlambda the smallest
// positive root of Peridigm's cubic, solved in closed form as Peridigm solves it. Plain scalars, no throw.
namespace pf {

// Peridigm's closed form (updateDeltaLambda): the smallest positive root of the monic cubic
// dl^3 + a dl^2 + b dl + c = 0 equivalent to the consistency condition
//   g(dl) = |t^d_tr|^2 / (2 (1 + alpha dl)^2) - psi0 - H (lambdaN + dl) = 0,
// by trigonometric roots when R^2 < Q^3, Cardano otherwise; 0 when no root is positive. H > 0.
// tdNorm = |t^d_tr| (sum over the family with V_j), psi0 = Peridigm's pointwise yield value,
// alpha = s 15 mu / m, H = Peridigm's Hardening Modulus.
double peridigmCubicRoot(double tdNorm, double lambdaN, double psi0, double alpha, double H);

// dlambda >= 0 of one node. 0 unless |t^d_tr|^2/2 > psi0 (Peridigm's trigger). H = 0 (where Peridigm divides
// by zero): the limit, Peridigm's perfectly plastic dl = (tdNorm / sqrt(2 psi0) - 1) / alpha (elastic_plastic.cxx).
// Otherwise peridigmCubicRoot, kept when it satisfies g = 0 to 1e-10 |t^d_tr|^2/2 -- always where the cubic is
// well conditioned, so the result is Peridigm's; where it is not (H << psi0 alpha, e.g. H = 2e10 with psi0 alpha
// ~ 1e54) the closed form returns rounding noise (0, or roots ~1e36/alpha) and g = 0 is solved by Newton.
double peridigmDeltaLambda(double tdNorm, double lambdaN, double psi0, double alpha, double H);

}  // namespace pf
