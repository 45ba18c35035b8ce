#pragma once
// Drives one peridynamic material point (MaterialPoint) and the classical J2 reference (ClassicalJ2)
// along the same small-strain path (F = I + eps) and collects the largest differences.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ClassicalJ2.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace pftest {

constexpr double kE = 200e9, kNu = 0.3, kSy = 600e6, kDx = 1e-3;

// CyclicShear: pure shear 0 -> +amp -> -amp -> +amp, where the third moment of t^d vanishes throughout.
enum class Path { Uniaxial, Cyclic, Shear, CyclicShear };
inline const char* pathName(Path p) {
  return p == Path::Uniaxial ? "uniaxial" : p == Path::Cyclic ? "cyclic" : p == Path::Shear ? "shear" : "cyclic shear";
}
inline bool isCyclic(Path p) { return p == Path::Cyclic || p == Path::CyclicShear; }

inline const char* dimName(pf::Dimension d) {
  return d == pf::Dimension::ThreeD ? "3D" : d == pf::Dimension::PlaneStress ? "PlaneStress" : "PlaneStrain";
}

// Controlling strain at step k of n: uniaxial/shear 0 -> amp; cyclic 0 -> +amp -> -amp -> +amp.
inline double pathStrain(Path p, int k, int n, double amp) {
  const double t = double(k) / n;
  if (!isCyclic(p)) return amp * t;
  if (t <= 0.25) return 4 * t * amp;
  if (t <= 0.75) return amp * (1 - 4 * (t - 0.25));
  return amp * (-1 + 8 * (t - 0.75));
}

// Small-strain tensor of the path (uniaxial strain along x, or pure shear eps_xy = eps_yx = s/2).
inline Sym pathTensor(Path p, double s) {
  Sym e{};
  if (p == Path::Shear || p == Path::CyclicShear) { e[1] = e[3] = 0.5 * s; } else { e[0] = s; }
  return e;
}

inline std::map<std::string, double> j2Values(pf::Dimension dim, double K, double H) {
  std::map<std::string, double> v = {{"Density", 8000.0}, {"Young's Modulus", kE}, {"Poisson's Ratio", kNu},
                                     {"Yield Stress", kSy}, {"Isotropic Hardening Modulus", K},
                                     {"Kinematic Hardening Modulus", H},
                                     // the paper's model: without Peridigm's factor (default true in 3D)
                                     {"Apply Shear Correction Factor", 0.0}};
  if (dim == pf::Dimension::PlaneStress) { v["Plane Stress"] = 1.0; v["Thickness"] = kDx; }
  if (dim == pf::Dimension::PlaneStrain) { v["Plane Strain"] = 1.0; v["Thickness"] = kDx; }
  return v;
}

struct PathResult {
  double vmErr = 0;      // max |vm_pd - vm_cl| / sigma_y
  double alphaErr = 0;   // max |alpha_pd - alpha_cl| / max alpha_cl
  double onsetErr = 0;   // |eps_y,pd / eps_y,cl - 1|: strain of first yield along the path (yieldOnset)
  double stressErr = 0;  // max in-plane |sigma_pd - sigma_cl| component / sigma_y (information)
  // Plane stress only (else -1): the same von Mises / alpha errors against the classical model with the
  // PD model's *scalar* back stress (PlaneStressJ2::Kinematic::Scalar) -- the model's own classical
  // counterpart. Equal to vmErr/alphaErr for H = 0; differs from them only by the scalar-vs-tensor back
  // stress (model form) for H > 0.
  double vmErrScalar = -1, alphaErrScalar = -1;
  int vmErrStep = 0;     // step of the largest von Mises error (against ClassicalJ2)
  int maxIterations = 0;
  int reverseYieldStepPd = -1, reverseYieldStepCl = -1;  // first plastic step after the first reversal
  // Plastic work per volume at the end of the path: the model's Dissipated_Energy / V, and the classical
  // sum sigma_n+1 : (eps^p_n+1 - eps^p_n) of ClassicalJ2 (backward Euler, as its return)
  double plasticWork = 0, plasticWorkCl = 0;
  std::vector<double> strain, vm, svm, alpha, lambda, q;  // per step, peridynamic
};

inline std::array<double, 9> pathF(pf::Dimension dim, const Sym& e) {
  std::array<double, 9> F{1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int a = 0; a < 9; ++a) F[a] += e[a];
  if (dim != pf::Dimension::ThreeD) F[8] = 1.0;
  return F;
}

// Amplitude s of the path's first loading branch at which the state first yields, from the virgin state in
// one step (bisection to 1e-12 relative on "yielded = plastic strain > 0"); yielded(s) must not commit.
template <class Yielded> double firstYield(Yielded yielded, double hi) {
  double lo = 0;
  while (!yielded(hi)) hi *= 2;
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (yielded(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The yield onset of a material point along the path's loading direction (uniaxial strain for the cyclic
// path), and of the classical model: an error here is an error of the yield stress as the model sees it,
// not of the elastic stiffness (which the first path step alone would measure).
inline double yieldOnsetError(pf::MaterialPoint& mp, pf::Dimension dim, Path path, ClassicalJ2 cl) {
  const Path dir = path == Path::Shear || path == Path::CyclicShear ? Path::Shear : Path::Uniaxial;
  const double sPd = firstYield([&](double s) {
    mp.deform(pathF(dim, pathTensor(dir, s)));
    mp.evaluate();  // from the committed (virgin) state; never committed
    return mp.value("Equivalent_Plastic_Strain") > 0;
  }, 1e-3);
  const double sCl = firstYield([&](double s) { cl.update(pathTensor(dir, s)); return cl.alphaT > 0; }, 1e-3);
  return std::fabs(sPd / sCl - 1.0);
}

struct PathOptions {
  double amp = 0.012;
  int steps = 120;
  std::string norm = "Discrete";
  bool partialVolume = false;
  std::string model = "Elastic Plastic Hardening";  // "Elastic Plastic": K and H must be 0
  pf::Influence influence = pf::Influence(pf::Influence::One);
};

inline PathResult runPath(pf::Dimension dim, double ratio, Path path, double K, double H, const PathOptions& o);

inline PathResult runPath(pf::Dimension dim, double ratio, Path path, double K, double H, double amp = 0.012,
                          int steps = 120, const std::string& norm = "Discrete", bool partialVolume = false) {
  PathOptions o;
  o.amp = amp; o.steps = steps; o.norm = norm; o.partialVolume = partialVolume;
  return runPath(dim, ratio, path, K, H, o);
}

inline PathResult runPath(pf::Dimension dim, double ratio, Path path, double K, double H, const PathOptions& o) {
  const double amp = o.amp;
  const int steps = o.steps;
  auto values = j2Values(dim, K, H);
  if (o.model == "Elastic Plastic") { values.erase("Isotropic Hardening Modulus"); values.erase("Kinematic Hardening Modulus"); }
  auto mat = pf::makeMaterial(o.model, values, {{"Yield Normalization", o.norm}});
  pf::MaterialPoint mp(*mat, kDx, ratio, kDx, o.partialVolume, o.influence);
  const ClassicalJ2::Mode mode = dim == pf::Dimension::ThreeD       ? ClassicalJ2::Mode::ThreeD
                                 : dim == pf::Dimension::PlaneStress ? ClassicalJ2::Mode::PlaneStress
                                                                    : ClassicalJ2::Mode::PlaneStrain;
  ClassicalJ2 cl(kE, kNu, kSy, K, H, mode);
  PlaneStressJ2 sc = PlaneStressJ2::isotropic(kE, kNu, kSy, K, H, PlaneStressJ2::Kinematic::Scalar);
  const bool withScalar = dim == pf::Dimension::PlaneStress;
  PathResult r;
  r.onsetErr = yieldOnsetError(mp, dim, path, cl);
  if (withScalar) r.vmErrScalar = r.alphaErrScalar = 0;
  double alphaMax = 0, alphaMaxSc = 0, alphaPrevPd = 0, alphaPrevCl = 0;
  bool reversed = false;
  for (int k = 1; k <= steps; ++k) {
    const double s = pathStrain(path, k, steps, amp);
    const Sym e = pathTensor(path, s);
    mp.deform(pathF(dim, e));
    mp.evaluate();
    cl.update(e);
    const double vm = mp.value("Von_Mises_Stress"), al = mp.value("Equivalent_Plastic_Strain");
    if (std::fabs(vm - cl.vonMises()) / kSy > r.vmErr) { r.vmErr = std::fabs(vm - cl.vonMises()) / kSy; r.vmErrStep = k; }
    if (withScalar) {
      sc.update(e);
      r.vmErrScalar = std::max(r.vmErrScalar, std::fabs(vm - sc.vonMises()) / kSy);
      r.alphaErrScalar = std::max(r.alphaErrScalar, std::fabs(al - sc.alphaT));
      alphaMaxSc = std::max(alphaMaxSc, sc.alphaT);
      sc.commit();
    }
    alphaMax = std::max(alphaMax, cl.alphaT);
    r.alphaErr = std::max(r.alphaErr, std::fabs(al - cl.alphaT));
    const std::array<double, 9> sg = mp.stress();
    const int comps[3] = {0, 1, 4};
    for (int c : comps) r.stressErr = std::max(r.stressErr, std::fabs(sg[c] - cl.sigma[c]) / kSy);
    r.maxIterations = std::max(r.maxIterations, int(mp.value("Return_Mapping_Iterations")));
    if (isCyclic(path) && k > steps / 4) reversed = true;
    if (reversed && r.reverseYieldStepPd < 0 && al > alphaPrevPd) r.reverseYieldStepPd = k;
    if (reversed && r.reverseYieldStepCl < 0 && cl.alphaT > alphaPrevCl) r.reverseYieldStepCl = k;
    alphaPrevPd = al; alphaPrevCl = cl.alphaT;
    for (int a = 0; a < 9; ++a) r.plasticWorkCl += cl.sigma[a] * (cl.epT[a] - cl.ep[a]);
    r.plasticWork = mp.value("Dissipated_Energy") / mp.nodeVolume();
    r.strain.push_back(s); r.vm.push_back(vm); r.svm.push_back(mp.value("Signed_Von_Mises_Stress"));
    r.alpha.push_back(al); r.lambda.push_back(mp.value("Lambda")); r.q.push_back(mp.value("Back_Stress"));
    mp.commit();
    cl.commit();
  }
  r.alphaErr = alphaMax > 0 ? r.alphaErr / alphaMax : r.alphaErr;
  if (withScalar && alphaMaxSc > 0) r.alphaErrScalar /= alphaMaxSc;
  return r;
}

}  // namespace pftest
