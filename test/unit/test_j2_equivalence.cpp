// Material-point equivalence of the OSB J2 models with classical small-strain J2 (Simo & Hughes),
// at one interior lattice point with a complete family.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <iostream>

#include "J2PathRunner.hpp"

using namespace pftest;
using pf::Dimension;

namespace {

struct Hardening { const char* name; double K, H; };
const Hardening kHardening[] = {{"perfect", 0, 0}, {"iso", 20e9, 0}, {"kin", 0, 20e9}, {"mixed", 20e9, 20e9}};
const Dimension kDims[] = {Dimension::ThreeD, Dimension::PlaneStrain, Dimension::PlaneStress};

}  // namespace

// Von Mises within 1 % of sigma_y, equivalent plastic strain within 1 % of its peak and yield onset within
// 1 % (3D, plane strain); 2 % in plane stress. sigma_y is the scale because the stress error of a lattice
// point is an elastic-stiffness error (the grid's anisotropic fourth moment, design doc) times the stress
// swing, up to 2 sigma_bar on a cycle. That error reaches 1 % only at delta/dx = 15 (3D) and 30 (2D, whose
// lattice error oscillates with delta/dx: 12 is good, 15 is bad); the return mapping itself is exact to
// round-off in 3D and plane strain (radial).
// Plane-stress cyclic paths with H > 0: the von Mises stress is checked against the classical model with
// the PD model's scalar back stress (PlaneStressJ2, Scalar), not the tensor one: uniaxial strain in plane
// stress is non-proportional in stress space, and the two classical models themselves differ by 1.97 %
// (kin) / 2.17 % (mixed) of sigma_y -- a model-form limit that no delta/dx removes (test below). Plastic
// strain and yield onset are still checked against the tensor model.
TEST(J2Equivalence, MatchesClassicalJ2) {
  for (Dimension dim : kDims) {
    const double ratio = dim == Dimension::ThreeD ? 15.0 : 30.0;
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
        const double tol = dim == Dimension::PlaneStress ? 0.02 : 0.01;
        const bool scalarRef = dim == Dimension::PlaneStress && path == Path::Cyclic && h.H > 0;
        const PathResult r = runPath(dim, ratio, path, h.K, h.H);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name + " " + pathName(path));
        EXPECT_LT(scalarRef ? r.vmErrScalar : r.vmErr, tol);
        EXPECT_LT(r.alphaErr, tol);
        EXPECT_LT(r.onsetErr, tol);
        EXPECT_LE(r.maxIterations, 10);
      }
  }
}

// The plane-stress reference itself: ClassicalJ2 (3D radial return, eps_zz iterated to sigma_zz = 0) and
// the Simo-Taylor projected plane-stress return (PlaneStressJ2, Tensor) are independent implementations
// of the same backward-Euler update; they agree to round-off on every path and hardening.
TEST(J2Equivalence, ClassicalPlaneStressReferencesAgree) {
  for (const Hardening& h : kHardening)
    for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
      ClassicalJ2 a(kE, kNu, kSy, h.K, h.H, ClassicalJ2::Mode::PlaneStress);
      PlaneStressJ2 b = PlaneStressJ2::isotropic(kE, kNu, kSy, h.K, h.H, PlaneStressJ2::Kinematic::Tensor);
      double dvm = 0, dal = 0, ds = 0;
      for (int k = 1; k <= 120; ++k) {
        const Sym e = pathTensor(path, pathStrain(path, k, 120, 0.012));
        a.update(e); b.update(e);
        const auto sb = b.stress();
        dvm = std::max(dvm, std::fabs(a.vonMises() - b.vonMises()));
        dal = std::max(dal, std::fabs(a.alphaT - b.alphaT));
        ds = std::max({ds, std::fabs(a.sigma[0] - sb[0]), std::fabs(a.sigma[4] - sb[1]), std::fabs(a.sigma[1] - sb[2])});
        a.commit(); b.commit();
      }
      SCOPED_TRACE(std::string(h.name) + " " + pathName(path));
      EXPECT_LT(dvm, 1e-10 * kSy);
      EXPECT_LT(ds, 1e-10 * kSy);
      EXPECT_LT(dal, 1e-12);
    }
}

// Model-form limit of the scalar back stress in plane stress (why cyclic plane stress with H > 0 is not
// held to 2 % against tensor J2). Measured (von Mises error / sigma_y, % ; PD = this lattice point):
//   scalar-back-stress J2 vs tensor J2, both classical (no lattice): kin 1.97, mixed 2.17, at step 98
//   (elastic re-loading after the second reversal, sigma_11 ~ 0, where the von Mises stress is carried by
//   sigma_22, which differs by ~12 MPa: with flow along s the plastic stress ratio sigma_22/sigma_11 on the
//   compressive plateau is 0.481 instead of the tensor model's 0.468 (flow along s - b)); iso/perfect 0,
//   monotonic uniaxial <= 0.05, shear 0.
//   PD vs tensor J2, delta/dx = 10, 12, 15, 20, 30, 40, 60: kin 1.85, 1.96, 1.88, 1.90, 1.92, 1.93, 1.94;
//   mixed 2.39, 2.24, 2.17, 2.18, 2.19, 2.19, 2.20 -> tends to the classical gap, not to 0;
//   PD vs scalar J2, same ratios: kin 1.85, 0.34, 1.16, 0.78, 0.51, 0.43, 0.24; mixed 3.08, 0.43, 1.94,
//   1.31, 0.88, 0.73, 0.43 -> tends to 0 like the lattice error of iso (3.34, 0.49, 2.11, 1.43, 0.97,
//   0.81, 0.49 vs tensor J2).
// So the 2 % bound of the issue is unreachable for mixed hardening by any delta/dx (limit 2.17 %), and kin
// meets it at 30 only by 0.08 %. A regression in the PD return moves PD away from its scalar counterpart
// (checked at 1 % / 0.5 %) and from the limit; a change of either classical model moves the gap.
TEST(J2Equivalence, PlaneStressKinematicCyclicModelFormLimit) {
  using KM = PlaneStressJ2::Kinematic;
  struct Case { const Hardening* h; double gap; };
  const Case cases[] = {{&kHardening[2], 0.0197}, {&kHardening[3], 0.0217}};
  for (const Hardening& h : kHardening)
    for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
      PlaneStressJ2 t = PlaneStressJ2::isotropic(kE, kNu, kSy, h.K, h.H, KM::Tensor);
      PlaneStressJ2 s = PlaneStressJ2::isotropic(kE, kNu, kSy, h.K, h.H, KM::Scalar);
      double gap = 0;
      int at = 0;
      for (int k = 1; k <= 120; ++k) {
        const Sym e = pathTensor(path, pathStrain(path, k, 120, 0.012));
        t.update(e); s.update(e);
        const double d = std::fabs(t.vonMises() - s.vonMises()) / kSy;
        if (d > gap) { gap = d; at = k; }
        t.commit(); s.commit();
      }
      SCOPED_TRACE(std::string(h.name) + " " + pathName(path));
      double expected = 0;
      for (const Case& c : cases)
        if (c.h == &h && path == Path::Cyclic) expected = c.gap;
      if (expected > 0) {
        EXPECT_NEAR(gap, expected, 2e-4);
        EXPECT_EQ(at, 98);
      } else {
        EXPECT_LT(gap, h.H > 0 ? 1e-3 : 1e-12);  // proportional enough (monotonic) or no back stress
      }
    }
  for (const Case& c : cases)
    for (double ratio : {30.0, 60.0}) {
      const PathResult r = runPath(Dimension::PlaneStress, ratio, Path::Cyclic, c.h->K, c.h->H);
      SCOPED_TRACE(std::string(c.h->name) + " delta/dx = " + std::to_string(int(ratio)));
      EXPECT_LT(r.vmErrScalar, ratio == 60.0 ? 0.005 : 0.01);  // lattice error against its own model
      EXPECT_NEAR(r.vmErr, c.gap, 0.001);                      // against tensor J2: the model-form limit
      EXPECT_GE(r.vmErrStep, 94);                              // ... located at the second reversal
      EXPECT_LE(r.vmErrStep, 98);
    }
}

// delta/dx = 10 (the brief's minimum): monotonic paths are within 1 % in 3D; the rest is the lattice
// error above (up to 1.9 % in 3D, 4.1 % in plane strain, 3.4 % in plane stress). Guards against
// regressions at the measured level.
TEST(J2Equivalence, RatioTenWithinMeasuredLatticeError) {
  for (Dimension dim : kDims)
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
        const PathResult r = runPath(dim, 10.0, path, h.K, h.H);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name + " " + pathName(path));
        const double tol = dim == Dimension::ThreeD ? (path == Path::Cyclic ? 0.02 : 0.01) : 0.045;
        EXPECT_LT(r.vmErr, tol);
        EXPECT_LT(r.alphaErr, tol);
        EXPECT_LT(r.onsetErr, tol);
      }
}

TEST(J2Equivalence, BauschingerReverseYieldWhereClassicalReverses) {
  for (Dimension dim : kDims)
    for (const Hardening& h : kHardening) {
      const PathResult r = runPath(dim, 10.0, Path::Cyclic, h.K, h.H);
      SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name);
      ASSERT_GT(r.reverseYieldStepCl, 0);
      EXPECT_LE(std::abs(r.reverseYieldStepPd - r.reverseYieldStepCl), 1);
    }
}

// Error table (model x dimension x path) at delta/dx = 3, 4, 10 (and 15 in 3D, 30 in 2D), both yield
// normalisations: printed for docs/materials.md and asserted. Bounds: the largest von Mises / plastic
// strain / yield-onset error over the 12 cases (hardening x path) of each row, as measured (2026-12-02),
// rounded up by about 10 % (a regression guard on the table docs/materials.md quotes; the physics bounds
// are MatchesClassicalJ2's). A change of either normalisation's constant by 2 % moves the onset column
// by 1 % and fails some row.
namespace {
struct TableBound { const char* norm; double ratio; Dimension dim; double vm, alpha, onset; };
const TableBound kTableBounds[] = {
    {"Discrete", 3, Dimension::ThreeD, 21.01, 14.06, 10.37},
    {"Discrete", 3, Dimension::PlaneStrain, 3.03, 3.15, 2.01},
    {"Discrete", 3, Dimension::PlaneStress, 3.07, 3.15, 2.01},
    {"Discrete", 4, Dimension::ThreeD, 3.79, 2.35, 1.59},
    {"Discrete", 4, Dimension::PlaneStrain, 4.05, 4.18, 2.69},
    {"Discrete", 4, Dimension::PlaneStress, 3.45, 4.18, 2.69},
    {"Discrete", 6, Dimension::ThreeD, 7.44, 4.82, 3.33},
    {"Discrete", 10, Dimension::ThreeD, 2.03, 1.15, 0.76},
    {"Discrete", 10, Dimension::PlaneStrain, 4.48, 4.16, 2.54},
    {"Discrete", 10, Dimension::PlaneStress, 3.69, 4.16, 2.54},
    {"Discrete", 15, Dimension::ThreeD, 0.77, 0.30, 0.19},
    {"Discrete", 30, Dimension::PlaneStrain, 1.07, 0.91, 0.58},
    {"Discrete", 30, Dimension::PlaneStress, 2.42, 0.91, 0.58},
    {"Continuum", 3, Dimension::ThreeD, 42.00, 14.93, 19.60},
    {"Continuum", 3, Dimension::PlaneStrain, 6.35, 5.35, 5.80},
    {"Continuum", 3, Dimension::PlaneStress, 7.97, 6.39, 5.80},
    {"Continuum", 4, Dimension::ThreeD, 8.09, 4.42, 5.05},
    {"Continuum", 6, Dimension::ThreeD, 13.21, 4.86, 5.43},
    {"Continuum", 4, Dimension::PlaneStrain, 9.93, 5.13, 3.89},
    {"Continuum", 4, Dimension::PlaneStress, 9.96, 5.13, 2.63},
    {"Continuum", 10, Dimension::ThreeD, 0.93, 1.36, 0.95},
    {"Continuum", 10, Dimension::PlaneStrain, 7.07, 4.62, 2.86},
    {"Continuum", 10, Dimension::PlaneStress, 6.49, 4.62, 1.81},
    {"Continuum", 15, Dimension::ThreeD, 0.97, 0.30, 0.26},
    {"Continuum", 30, Dimension::PlaneStrain, 0.81, 0.88, 0.82},
    {"Continuum", 30, Dimension::PlaneStress, 2.37, 0.88, 0.82},
};
}  // namespace

TEST(J2Equivalence, ErrorTable) {
  for (const TableBound& b : kTableBounds) {
    double vm = 0, al = 0, on = 0;
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
        const PathResult r = runPath(b.dim, b.ratio, path, h.K, h.H, 0.012, 120, b.norm);
        char sc[16] = "-";
        if (r.vmErrScalar >= 0) std::snprintf(sc, sizeof sc, "%.2f", 100 * r.vmErrScalar);
        std::printf("| %s | %g | %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %d | %s |\n", b.norm, b.ratio,
                    dimName(b.dim), h.name, pathName(path), 100 * r.vmErr, 100 * r.alphaErr, 100 * r.onsetErr,
                    100 * r.stressErr, r.maxIterations, sc);
        vm = std::max(vm, 100 * r.vmErr); al = std::max(al, 100 * r.alphaErr); on = std::max(on, 100 * r.onsetErr);
      }
    std::printf("max | %s | %g | %s | %.2f | %.2f | %.2f |\n", b.norm, b.ratio, dimName(b.dim), vm, al, on);
    SCOPED_TRACE(std::string(b.norm) + " " + dimName(b.dim) + " ratio " + std::to_string(b.ratio));
    EXPECT_LE(vm, b.vm);
    EXPECT_LE(al, b.alpha);
    EXPECT_LE(on, b.onset);
  }
  std::fflush(stdout);
}

// The plane-stress convergence study behind PlaneStressKinematicCyclicModelFormLimit, cyclic path: von
// Mises error (% of sigma_y) against tensor J2 and against the scalar-back-stress J2 at delta/dx = 10 ..
// 60, as docs/materials.md quotes them (to 0.01 %: the numbers are printed to two decimals; round-off
// of the classical references is 1e-10).
TEST(J2Equivalence, PlaneStressConvergence) {
  struct Row { int h; double tensor[7], scalar[7]; };
  const double ratios[7] = {10, 12, 15, 20, 30, 40, 60};
  const Row rows[] = {{1, {3.34, 0.49, 2.11, 1.43, 0.97, 0.81, 0.49}, {3.34, 0.49, 2.11, 1.43, 0.97, 0.81, 0.49}},
                      {2, {1.85, 1.96, 1.88, 1.90, 1.92, 1.93, 1.94}, {1.85, 0.34, 1.16, 0.78, 0.51, 0.43, 0.24}},
                      {3, {2.39, 2.24, 2.17, 2.18, 2.19, 2.19, 2.20}, {3.08, 0.43, 1.94, 1.31, 0.88, 0.73, 0.43}}};
  for (const Row& row : rows)
    for (int k = 0; k < 7; ++k) {
      const Hardening& h = kHardening[row.h];
      const PathResult r = runPath(Dimension::PlaneStress, ratios[k], Path::Cyclic, h.K, h.H);
      std::printf("| %g | %s | cyclic | %.2f | %d | %.2f | %.2f |\n", ratios[k], h.name, 100 * r.vmErr, r.vmErrStep,
                  100 * r.vmErrScalar, 100 * r.alphaErr);
      SCOPED_TRACE(std::string(h.name) + " ratio " + std::to_string(ratios[k]));
      EXPECT_NEAR(100 * r.vmErr, row.tensor[k], 0.0051);
      EXPECT_NEAR(100 * r.vmErrScalar, row.scalar[k], 0.0051);
    }
  std::fflush(stdout);
}


// Partial-volume families (Discretization "Partial Volume", MaterialPoint partialVolume): each bond
// weighted by the share of its cell inside the horizon, which makes the lattice family's fourth moment
// nearly isotropic (test_partial_volume.cpp).
// At delta/dx = 10 the bounds hold: 1 % in 3D and plane strain, 2 % in plane stress (measured
// max 0.29 % everywhere except plane-stress cyclic paths with H > 0, where the von Mises stress is held
// against the scalar-back-stress J2 as in MatchesClassicalJ2: against tensor J2 they are 1.95 % / 2.20 %,
// the model-form gap of that test). Without partial volumes the same ratio gives 1.8 % (3D) and 4.1 %
// (plane strain) on cyclic paths (RatioTenWithinMeasuredLatticeError).
// At delta/dx = 6 (Peridigm's default Continuum yield value at a spherical family: 12.01 % in 3D without partial
// volumes, Discrete 6.76 %, ErrorTable) the 3 % (issue 38; measured with partial volumes: 3D 0.26 %, plane
// strain 0.27 %, plane stress 2.20 %, its cyclic paths with H > 0 against tensor J2 -- the model-form gap above -- and
// 0.34 % elsewhere).
// At the paper's delta/dx = 3, 4, 5 (whole volumes: up to 19 %, 3.7 %, see docs/materials.md) the bounds
// are the largest errors measured over the 12 cases of each ratio and dimension, rounded up by ~25 % (a
// regression guard, not a physical limit): von Mises / plastic strain / onset in %.
TEST(J2Equivalence, PartialVolumeFamilies) {
  struct Bound { double ratio; Dimension dim; double vm, other; };
  const Bound bounds[] = {{3, Dimension::ThreeD, 1.1, 0.75},     {3, Dimension::PlaneStrain, 1.9, 1.9},
                          {3, Dimension::PlaneStress, 3.1, 1.9},  {4, Dimension::ThreeD, 0.5, 0.35},
                          {4, Dimension::PlaneStrain, 0.8, 0.7},  {4, Dimension::PlaneStress, 2.9, 0.7},
                          {5, Dimension::ThreeD, 0.35, 0.2},     {5, Dimension::PlaneStrain, 0.5, 0.4},
                          {5, Dimension::PlaneStress, 2.8, 0.4},  {6, Dimension::ThreeD, 3.0, 3.0},
                          {6, Dimension::PlaneStrain, 3.0, 3.0},  {6, Dimension::PlaneStress, 3.0, 3.0},
                          {10, Dimension::ThreeD, 1.0, 1.0},
                          {10, Dimension::PlaneStrain, 1.0, 1.0}, {10, Dimension::PlaneStress, 2.0, 2.0}};
  std::printf("\nPartial Volume, Discrete normalisation (%%): max |vm - vm_J2|/sy, max |alpha - alpha_J2|/max "
              "alpha_J2, onset; plane stress also vs scalar-q J2\n");
  std::printf("| ratio | dim | hardening | path | von Mises | eq. plastic strain | yield onset | Newton its | "
              "von Mises vs scalar-q J2 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Bound& b : bounds)
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
        const PathResult r = runPath(b.dim, b.ratio, path, h.K, h.H, 0.012, 120, "Discrete", true);
        char sc[16] = "-";
        if (r.vmErrScalar >= 0) std::snprintf(sc, sizeof sc, "%.2f", 100 * r.vmErrScalar);
        std::printf("| %g | %s | %s | %s | %.2f | %.2f | %.2f | %d | %s |\n", b.ratio, dimName(b.dim), h.name,
                    pathName(path), 100 * r.vmErr, 100 * r.alphaErr, 100 * r.onsetErr, r.maxIterations, sc);
        SCOPED_TRACE(std::string(dimName(b.dim)) + " " + h.name + " " + pathName(path) + " ratio " +
                     std::to_string(b.ratio));
        const bool scalarRef = b.dim == Dimension::PlaneStress && path == Path::Cyclic && h.H > 0;
        EXPECT_LT(100 * ((scalarRef && b.ratio == 10) ? r.vmErrScalar : r.vmErr), b.vm);
        EXPECT_LT(100 * r.alphaErr, b.other);
        EXPECT_LT(100 * r.onsetErr, b.other);
        EXPECT_LE(r.maxIterations, 10);
      }
  std::fflush(stdout);
}

// Cyclic pure shear (eps_xy 0 -> +1.2 -> -1.2 -> +1.2 %): the third moment of t^d vanishes along the whole path, so
// the paper's sign of sigma_vm never turns and a back stress q > 0 cannot show the Bauschinger effect. 3D and
// plane strain orient q by the committed plastic extension instead (OsbJ2SignRule::PlasticExtension): von
// Mises within 1 % of sigma_y of tensor J2 with H > 0 as for the other paths (measured, ratio 15 / 30: kin 0.22 /
// 0.88 %, mixed 0.24 / 0.98 %; with the third-moment sign 1.92 / 1.90 % and 4.33 / 4.67 %). Plane stress keeps the
// paper's sign (kin 6.73 %, mixed 4.67 %: docs/materials.md, limitation (i)). Only H > 0 is at stake: with H = 0 the
// sign does not enter, and plane strain's perfect / iso errors on this path (0.99 / 1.05 %) are the lattice's over
// a 2 sigma_bar swing, as on the uniaxial cycle.
TEST(J2Equivalence, CyclicPureShearFollowsTensorJ2) {
  for (Dimension dim : {Dimension::ThreeD, Dimension::PlaneStrain}) {
    const double ratio = dim == Dimension::ThreeD ? 15.0 : 30.0;
    for (const Hardening& h : kHardening) {
      if (h.H == 0) continue;
      const PathResult r = runPath(dim, ratio, Path::CyclicShear, h.K, h.H);
      SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name);
      EXPECT_LT(r.vmErr, 0.01);
      EXPECT_LT(r.alphaErr, 0.01);
      ASSERT_GT(r.reverseYieldStepCl, 0);
      EXPECT_LE(std::abs(r.reverseYieldStepPd - r.reverseYieldStepCl), 1);
    }
  }
}

// The plastic work the J2 models integrate (Dissipated_Energy, sigma_vm |d eps_p| V per step; the heat source of the
// Taylor-Quinney coefficient) against the classical sum sigma_n+1 : (eps^p_n+1 - eps^p_n) of ClassicalJ2 over the
// same paths, cyclic pure shear included. Bound 2 %: W_p = sum sigma_bar d alpha carries the relative von Mises error
// (within 1 % of sigma_y <= sigma_bar, MatchesClassicalJ2) plus the relative plastic strain error (within 1 %), at
// 3D 15 and 2D 30. Measured: 3D max 0.33 %, plane strain 1.00 %, plane stress 1.00 % (the shear paths).
TEST(J2Equivalence, PlasticWorkMatchesClassicalJ2) {
  for (Dimension dim : kDims) {
    const double ratio = dim == Dimension::ThreeD ? 15.0 : 30.0;
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear, Path::CyclicShear}) {
        const PathResult r = runPath(dim, ratio, path, h.K, h.H);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name + " " + pathName(path));
        ASSERT_GT(r.plasticWorkCl, 0.0);
        EXPECT_LT(std::fabs(r.plasticWork / r.plasticWorkCl - 1.0), 0.02);
      }
  }
}
