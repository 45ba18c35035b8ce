#include "CorrespondenceKinematics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/InputError.hpp"
#include "core/Material.hpp"

namespace pf {
namespace {

std::string pointName(const FamilyView& fam, int i) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "the point at (%.6g, %.6g, %.6g)", fam.x[3 * i], fam.x[3 * i + 1], fam.x[3 * i + 2]);
  return buf;
}

}  // namespace

ShapeAndGradient shapeAndGradient(const FamilyView& fam, int i, const double* y, bool planar) {
  ShapeAndGradient out;
  if (tryShapeAndGradient(fam, i, y, planar, out)) return out;
  const FamilySums s = familySums(fam, i, y, planar);
  throw InputError("correspondence model: the shape tensor K of " + pointName(fam, i) + " is singular (" +
                   std::to_string(s.bonds) + " bonds; det K / (tr K / d)^d = " + std::to_string(s.quality) +
                   "): its family needs " + (planar ? "two non-parallel bonds" : "three non-coplanar bonds") +
                   "; is the horizon too small for the grid?");
}

void requirePositiveJacobian(const FamilyView& fam, int i, const double* y, const Mat3& F) {
  const double J = det(F);
  if (J > 0.0) return;
  // The neighbours' state tells a squeezed or inverted family (bonds turned around: the deformed bond points
  // against the reference one) from a blown-up one (a stretch far beyond any material's).
  int bonds = 0, turned = 0;
  double stretchMin = HUGE_VAL, stretchMax = -HUGE_VAL;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const int j = fam.neighbors[b];
    if (bondWeight(fam, b) == 0.0) continue;
    double dot = 0.0, l0 = 0.0, l = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double xi = fam.x[3 * j + a] - fam.x[3 * i + a], Y = y[3 * j + a] - y[3 * i + a];
      dot += xi * Y, l0 += xi * xi, l += Y * Y;
    }
    ++bonds, turned += dot < 0.0;
    const double stretch = std::sqrt(l / l0) - 1.0;
    stretchMin = std::min(stretchMin, stretch), stretchMax = std::max(stretchMax, stretch);
  }
  char buf[700];
  std::snprintf(buf, sizeof buf,
                "correspondence model: det F = %.3g <= 0 at %s, displaced by (%.3g, %.3g, %.3g): of its %d bonds %d "
                "point against their reference direction, bond stretches %.3g .. %.3g (a family turned inside out: "
                "a body squeezed through itself or a wall, a wall normal pointing into the body, a time step or "
                "load step too large, or too little hourglass stiffness)",
                J, pointName(fam, i).c_str(), y[3 * i] - fam.x[3 * i], y[3 * i + 1] - fam.x[3 * i + 1],
                y[3 * i + 2] - fam.x[3 * i + 2], bonds, turned, stretchMin, stretchMax);
  throw ConstitutiveFailure(buf);
}

namespace {

// Omega dt from a left stretch V and the increments D dt, W dt: z_i = e_ijk (V D)_jk, w_i = -e_ijk W_jk / 2,
// omega = w + (tr V I - V)^-1 z, Omega_ij = e_ikj omega_k (T&F Eqs. 10-13; Peridigm's correspondence.cxx the same).
Mat3 spinIncrement(const Mat3& V, const Mat3& D, const Mat3& W) {
  const Mat3 A = mul(V, D);
  const double z[3] = {A[5] - A[7], A[6] - A[2], A[1] - A[3]};
  const double w[3] = {W[7], W[2], W[3]};
  Mat3 Minv;
  if (!(std::fabs(inverse(trace(V) * identity3() - V, Minv)) > 0.0))
    throw ConstitutiveFailure("correspondence model: tr(V) I - V is singular in the Flanagan-Taylor update");
  double om[3];
  for (int a = 0; a < 3; ++a) om[a] = w[a] + Minv[3 * a] * z[0] + Minv[3 * a + 1] * z[1] + Minv[3 * a + 2] * z[2];
  return Mat3{0, -om[2], om[1], om[2], 0, -om[0], -om[1], om[0], 0};
}

// L dt = (F - F_n) G^-1 for G = F_mid (Periforge) or F (Peridigm, with F - F_n its Fdot dt).
Mat3 velocityGradientIncrement(const Mat3& Fn, const Mat3& F, const Mat3& G) {
  Mat3 Ginv;
  if (!(inverse(G, Ginv) > 0.0))
    throw ConstitutiveFailure("correspondence model: the deformation gradient is not invertible with det > 0 "
                              "(a family turned inside out)");
  return mul(F - Fn, Ginv);
}

}  // namespace

PolarUpdate flanaganTaylor(const Mat3& Fn, const Mat3& F, const Mat3& Rn, const Mat3& Vn) {
  const Mat3 L = velocityGradientIncrement(Fn, F, 0.5 * (Fn + F));  // L dt
  const Mat3 D = sym(L), W = skew(L);
  // Cayley map of a skew matrix: exactly orthogonal, and for a rigid rotation increment Q (where D = 0 and
  // W dt = 2 (Q - I)(Q + I)^-1) it returns Q itself.
  auto cayley = [](const Mat3& S) {
    Mat3 inv;
    inverse(identity3() - 0.5 * S, inv);  // I - S/2 is invertible for every skew S
    return mul(inv, identity3() + 0.5 * S);
  };
  // V enters the spin at the half step: a first pass with V_n predicts R there, V_h = sym(F_mid R_h^T); with
  // V_n alone the update is first order (the error in R halves with dt instead of quartering).
  const Mat3 Fmid = 0.5 * (Fn + F);
  const Mat3 Vh = sym(mulNT(Fmid, mul(cayley(0.5 * spinIncrement(Vn, D, W)), Rn)));
  const Mat3 Om = spinIncrement(Vh, D, W);
  PolarUpdate out;
  out.R = mul(cayley(Om), Rn);
  const Mat3 Rh = mul(cayley(0.5 * Om), Rn);
  out.V = sym(mulNT(F, out.R));
  out.dUnrot = mulTN(Rh, mul(D, Rh));
  return out;
}

PolarUpdate peridigmPolarUpdate(const Mat3& dFdt, const Mat3& F, const Mat3& Rn, const Mat3& Vn) {
  const Mat3 L = velocityGradientIncrement(Mat3{}, dFdt, F);  // Fdot F^-1 dt
  const Mat3 D = sym(L), W = skew(L);
  const Mat3 Om = spinIncrement(Vn, D, W);  // with V_n: first order
  // Peridigm's Q = I + sin(t)/t Om - (1 - cos t)/t^2 Om^2, t = |omega dt| (its sign of the second term; for a
  // step's small t the difference from the exponential map is O(t^2)).
  const double t2 = 0.5 * ddot(Om, Om), t = std::sqrt(t2);
  Mat3 Q = identity3();
  if (t > 0.0) Q = Q + (std::sin(t) / t) * Om - ((1.0 - std::cos(t)) / t2) * mul(Om, Om);
  PolarUpdate out;
  out.R = mul(Q, Rn);
  out.V = Vn + mul(L, Vn) - mul(Vn, Om);  // V_n + dt (L V_n - V_n Omega)
  out.dUnrot = mulTN(out.R, mul(D, out.R));
  return out;
}

Mat3 velocityGradient(const FamilyView& fam, int i, const double* v, const Mat3& Kinv, bool planar) {
  Mat3 Fdot = mul(familySums(fam, i, v, planar).N, Kinv);  // N: the sum of w (v_j - v_i) (x) xi
  if (planar) Fdot[2] = Fdot[5] = Fdot[6] = Fdot[7] = Fdot[8] = 0.0;
  return Fdot;
}

Mat3 piolaFromUnrotated(const Mat3& F, const Mat3& R, const Mat3& tau) {
  const Mat3 sigma = mul(R, mulNT(tau, R));
  Mat3 Finv;
  const double J = inverse(F, Finv);
  if (!(J > 0.0))
    throw ConstitutiveFailure("correspondence model: det F <= 0 (a family turned inside out)");
  return J * mulNT(sigma, Finv);
}

void addCorrespondenceForce(const FamilyView& fam, int i, const Mat3& A, double* force) {
  const double* xi0 = fam.x + 3 * i;
  const double vi = fam.volume[i];
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const int j = fam.neighbors[b];
    const double w = fam.unitInfluence ? 1.0 : fam.influence[b];
    const double frac = fam.fraction ? fam.fraction[b] : 1.0;
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    for (int a = 0; a < 3; ++a) {
      const double T = w * (A[3 * a] * xi[0] + A[3 * a + 1] * xi[1] + A[3 * a + 2] * xi[2]);
      force[3 * i + a] += T * fam.volume[j] * frac;
      force[3 * j + a] -= T * vi * frac;
    }
  }
}

void addHourglassForce(const FamilyView& fam, int i, const double* y, const Mat3& F, double c, double* force) {
  if (c == 0.0) return;
  const double* xi0 = fam.x + 3 * i;
  const double* yi = y + 3 * i;
  const double vi = fam.volume[i];
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const int j = fam.neighbors[b];
    const double frac = fam.fraction ? fam.fraction[b] : 1.0;
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    const double Y[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
    const double len = std::sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
    if (len == 0.0) continue;
    double dot = 0.0;  // (Y - F xi) . Y
    for (int a = 0; a < 3; ++a)
      dot += (Y[a] - (F[3 * a] * xi[0] + F[3 * a + 1] * xi[1] + F[3 * a + 2] * xi[2])) * Y[a];
    const double mag = c * dot / (fam.refLength[b] * len * len);  // times Y: the unit vector and |Y| folded in
    for (int a = 0; a < 3; ++a) {
      force[3 * i + a] += mag * Y[a] * fam.volume[j] * frac;
      force[3 * j + a] -= mag * Y[a] * vi * frac;
    }
  }
}

namespace {

// The hourglass term of bond (i, j) at each end, as multiples of Y (addHourglassForce's mag): the term is odd
// in (Y, xi), so j's end adds c_j (Y - F_j xi) . Y / (|xi| |Y|^2) Y to f_i with the same sign as i's own.
inline void hourglassBothEnds(const double* Y, const double* xi, const double* Fi, const double* Fj, double ci,
                              double cj, double refLength, double& magi, double& magj) {
  const double len2 = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
  magi = magj = 0.0;
  if (len2 == 0.0) return;
  double di = 0.0, dj = 0.0;
  for (int a = 0; a < 3; ++a) {
    di += (Y[a] - (Fi[3 * a] * xi[0] + Fi[3 * a + 1] * xi[1] + Fi[3 * a + 2] * xi[2])) * Y[a];
    dj += (Y[a] - (Fj[3 * a] * xi[0] + Fj[3 * a + 1] * xi[1] + Fj[3 * a + 2] * xi[2])) * Y[a];
  }
  magi = ci * di / (refLength * len2);
  magj = cj * dj / (refLength * len2);
}

// The weights phi_j of the linear reconstruction of a field at x_i from i's neighbours alone (i's own value not
// used): sum phi_j = 1 and sum phi_j xi_j = 0, phi_j = a omega V_j (1 - m . xi_j) with m = K^-1 sum omega xi V_j
// (M1) and a = 1 / (M0 - M1 . m), M0 = sum omega V_j. bandForce needs only the scalar a and the vector m.
// Exact (both sums hold) when the summed bonds are the ones K was built from. a <= 0: the neighbours lie on one
// line (plane) off x_i and cannot reconstruct; returned as 0 (the caller then keeps the point's own value).
double linearReconstruction(const FamilyView& fam, int i, const Mat3& Kinv, const double* broken, double m[3]) {
  double M0 = 0.0, M1[3] = {0.0, 0.0, 0.0};
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    if (broken && broken[b] != 0.0) continue;
    const int j = fam.neighbors[b];
    const double w = fam.unitInfluence ? 1.0 : fam.influence[b];
    const double wv = w * fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
    M0 += wv;
    for (int a = 0; a < 3; ++a) M1[a] += wv * (fam.x[3 * j + a] - fam.x[3 * i + a]);
  }
  for (int r = 0; r < 3; ++r) m[r] = Kinv[3 * r] * M1[0] + Kinv[3 * r + 1] * M1[1] + Kinv[3 * r + 2] * M1[2];
  const double schur = M0 - (M1[0] * m[0] + M1[1] * m[1] + M1[2] * m[2]);
  return schur > 1e-12 * M0 ? 1.0 / schur : 0.0;
}

// addBandForce, with the hourglass part kept apart only when wanted (a compile-time choice: no cost otherwise).
// The difference form sum omega (P_j - P_i) K_i^-1 xi V_j holds the point's own stress in -P_i m (m as above):
// linearised, -dP_i m = C:(du_i (x) m) m, a negative stiffness C|m|^2 of the point against its own
// displacement (the energy form has +P_i m there: a positive one). On the outer layer the traction term -P_i n / dx
// outweighs it (n / dx against m); where a family is cut but the point has no exposed face (a staircase's
// re-entrant corner: 8 of 28 bonds cut, n = 0) nothing does, and the plate with a lattice hole had a growing mode
// there at Hourglass Coefficient 0.25 (test_surface_band.cpp). So the difference takes P-hat_i = sum phi_j P_j,
// i's stress reconstructed from its neighbours: equal to P_i for every linear P (Eqs. 31-32's exactness and the
// uniform-stress traction kept), with no dependence on u_i through P_i. The traction term keeps P_i.
template <bool kHourglass>
void bandForce(const FamilyView& fam, int i, const double* y, const Mat3& Kinv, const double* rows, int stride,
               double* force, const double* broken, double* hourglass) {
  const double* xi0 = fam.x + 3 * i;
  const double* yi = y + 3 * i;
  const double* ri = rows + static_cast<std::size_t>(stride) * i;
  const double* Pi = ri + kRowP;
  double m[3];
  const double a0 = linearReconstruction(fam, i, Kinv, broken, m);
  // Per bond, P_j times omega V_j (K^-1 xi - phi m): its share of the difference and of -P-hat_i m. With a0 = 0
  // (no reconstruction) the point's own P_i stands for P-hat_i, as in the paper's form.
  double f[3] = {0.0, 0.0, 0.0}, hg[3] = {0.0, 0.0, 0.0};
  if (a0 == 0.0)
    for (int a = 0; a < 3; ++a) f[a] -= Pi[3 * a] * m[0] + Pi[3 * a + 1] * m[1] + Pi[3 * a + 2] * m[2];
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    if (broken && broken[b] != 0.0) continue;
    const int j = fam.neighbors[b];
    const double* rj = rows + static_cast<std::size_t>(stride) * j;
    const double* Pj = rj + kRowP;
    const double w = fam.unitInfluence ? 1.0 : fam.influence[b];
    const double vj = fam.volume[j] * (fam.fraction ? fam.fraction[b] : 1.0);
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    const double Y[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
    const double phi = a0 * (1.0 - (m[0] * xi[0] + m[1] * xi[1] + m[2] * xi[2]));  // over omega V_j
    double kx[3];  // K_i^-1 xi - phi m
    for (int r = 0; r < 3; ++r)
      kx[r] = Kinv[3 * r] * xi[0] + Kinv[3 * r + 1] * xi[1] + Kinv[3 * r + 2] * xi[2] - phi * m[r];
    double magi, magj;
    hourglassBothEnds(Y, xi, ri + kRowF, rj + kRowF, ri[kRowC], rj[kRowC], fam.refLength[b], magi, magj);
    for (int a = 0; a < 3; ++a) {
      const double t = Pj[3 * a] * kx[0] + Pj[3 * a + 1] * kx[1] + Pj[3 * a + 2] * kx[2];
      f[a] += (w * t + (magi + magj) * Y[a]) * vj;
      if constexpr (kHourglass) hg[a] += (magi + magj) * Y[a] * vj;
    }
  }
  // Eq. 31's traction term -P_i n / dx; T_ext / dx comes from a Pressure condition: a dead load as its body
  // force, a follower one here, J F^-T times the reference traction (Nanson: the deformed area vector).
  const double* n = fam.outerNormal + 3 * i;
  const double h = fam.layerThickness[i];
  if (h > 0.0)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) f[a] -= Pi[3 * a + c] * n[c] / h;
  if (fam.followerLoad) {
    const double* q = fam.followerLoad + 3 * i;
    if (q[0] != 0.0 || q[1] != 0.0 || q[2] != 0.0) {
      const Mat3 cof = cofactor(ri + kRowF);
      for (int a = 0; a < 3; ++a) f[a] += cof[3 * a] * q[0] + cof[3 * a + 1] * q[1] + cof[3 * a + 2] * q[2];
    }
  }
  for (int a = 0; a < 3; ++a) force[3 * i + a] += f[a];
  if constexpr (kHourglass) std::copy(hg, hg + 3, hourglass);
}

template <bool kHourglass>
void gatheredForce(const FamilyView& fam, int i, const double* y, const double* rows, int stride, double* force,
                   const double* broken, double* hourglass) {
  const double* xi0 = fam.x + 3 * i;
  const double* yi = y + 3 * i;
  const double* Ai = rows + static_cast<std::size_t>(stride) * i;
  const double* Fi = Ai + kRowF;
  const double ci = Ai[kRowC];
  double f[3] = {0.0, 0.0, 0.0}, hg[3] = {0.0, 0.0, 0.0};
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    if (broken && broken[b] != 0.0) continue;
    const int j = fam.neighbors[b];
    const double* Aj = rows + static_cast<std::size_t>(stride) * j;
    const double* Fj = Aj + kRowF;
    const double cj = Aj[kRowC];
    const bool gathers = Aj[kRowFlag] != 0.0;
    const double w = fam.unitInfluence ? 1.0 : fam.influence[b];
    const double frac = fam.fraction ? fam.fraction[b] : 1.0;
    const double vj = fam.volume[j] * frac;
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    const double Y[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
    // Stress: T_i<xi> - T_j<-xi> = omega (A_i + A_j) xi (Foster Eq. 25 at both ends).
    double ti[3], tj[3];
    for (int a = 0; a < 3; ++a) {
      ti[a] = tj[a] = 0.0;
      for (int s = 0; s < 3; ++s) ti[a] += Ai[3 * a + s] * xi[s], tj[a] += Aj[3 * a + s] * xi[s];
      ti[a] *= w, tj[a] *= w;
    }
    double magi, magj;
    hourglassBothEnds(Y, xi, Fi, Fj, ci, cj, fam.refLength[b], magi, magj);
    for (int a = 0; a < 3; ++a) {
      f[a] += (ti[a] + tj[a] + (magi + magj) * Y[a]) * vj;
      if constexpr (kHourglass) hg[a] += (magi + magj) * Y[a] * vj;
      if (!gathers) force[3 * j + a] -= (ti[a] + magi * Y[a]) * fam.volume[i] * frac;
    }
  }
  for (int a = 0; a < 3; ++a) force[3 * i + a] += f[a];
  if constexpr (kHourglass) std::copy(hg, hg + 3, hourglass);
}

}  // namespace

void addBandForce(const FamilyView& fam, int i, const double* y, const Mat3& Kinv, const double* rows, int stride,
                  double* force, const double* broken, double* hourglass) {
  if (hourglass)
    bandForce<true>(fam, i, y, Kinv, rows, stride, force, broken, hourglass);
  else
    bandForce<false>(fam, i, y, Kinv, rows, stride, force, broken, nullptr);
}

void addGatheredForce(const FamilyView& fam, int i, const double* y, const double* rows, int stride, double* force,
                      const double* broken, double* hourglass) {
  if (hourglass)
    gatheredForce<true>(fam, i, y, rows, stride, force, broken, hourglass);
  else
    gatheredForce<false>(fam, i, y, rows, stride, force, broken, nullptr);
}

namespace {

// The hourglass force state of one bond (per V_i V_j), as addHourglassForce computes it.
void hourglassBond(const double* Y, const double* xi, const Mat3& F, double c, double refLength, double* T) {
  const double len2 = Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2];
  T[0] = T[1] = T[2] = 0.0;
  if (len2 == 0.0) return;
  double dot = 0.0;
  for (int a = 0; a < 3; ++a) dot += (Y[a] - (F[3 * a] * xi[0] + F[3 * a + 1] * xi[1] + F[3 * a + 2] * xi[2])) * Y[a];
  const double mag = c * dot / (refLength * len2);
  for (int a = 0; a < 3; ++a) T[a] = mag * Y[a];
}

}  // namespace

double hourglassWork(const FamilyView& fam, int i, const double* yN, const Mat3& FN, const double* y, const Mat3& F,
                     double c) {
  if (c == 0.0) return 0.0;
  const double* xi0 = fam.x + 3 * i;
  double w = 0.0;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const int j = fam.neighbors[b];
    const double frac = fam.fraction ? fam.fraction[b] : 1.0;
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    double Y[3], YN[3], T[3], TN[3];
    for (int a = 0; a < 3; ++a) Y[a] = y[3 * j + a] - y[3 * i + a], YN[a] = yN[3 * j + a] - yN[3 * i + a];
    hourglassBond(Y, xi, F, c, fam.refLength[b], T);
    hourglassBond(YN, xi, FN, c, fam.refLength[b], TN);
    // The force on i is +T V_j, on j -T V_i: the work the body does against them is -(their power), i.e.
    // the bond takes (T . (dY)) V_i V_j with T pulling i towards j when the bond is stretched beyond F xi.
    double dw = 0.0;
    for (int a = 0; a < 3; ++a) dw += 0.5 * (T[a] + TN[a]) * (Y[a] - YN[a]);
    w += dw * fam.volume[j] * frac;
  }
  return w * fam.volume[i];
}

}  // namespace pf
