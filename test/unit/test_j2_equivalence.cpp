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
// The convergence study behind PlaneStressKinematicCyclicModelFormLimit (run with
// --gtest_also_run_disabled_tests): plane-stress von Mises error (% of sigma_y) against tensor J2 and
// against the scalar-back-stress J2, and where the tensor error peaks.
TEST(J2Equivalence, DISABLED_PlaneStressConvergence) {
  std::printf("| delta/dx | hardening | path | vs tensor J2 | at step | vs scalar-q J2 | eq. plastic strain |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (double ratio : {10.0, 12.0, 15.0, 20.0, 30.0, 40.0, 60.0})
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic}) {
        if (h.K == 0 && h.H == 0) continue;
        const PathResult r = runPath(Dimension::PlaneStress, ratio, path, h.K, h.H);
        std::printf("| %g | %s | %s | %.2f | %d | %.2f | %.2f |\n", ratio, h.name, pathName(path), 100 * r.vmErr,
                    r.vmErrStep, 100 * r.vmErrScalar, 100 * r.alphaErr);
      }
  std::fflush(stdout);
}

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

// Error table (model x dimension x path) at delta/dx = 3, 4, 10 (and 15 in 3D, 30 in 2D) for
// docs/materials.md, for both yield normalisations.
TEST(J2Equivalence, ErrorTable) {
  for (const char* norm : {"Discrete", "Continuum"}) {
    std::printf("\nYield Normalization = %s: max |vm - vm_J2|/sy, max |alpha - alpha_J2|/max alpha_J2, "
                "onset, max in-plane stress component error/sy; plane stress: von Mises against classical J2 with "
                "the model's scalar back stress (%%)\n", norm);
    std::printf("| ratio | dim | hardening | path | von Mises | eq. plastic strain | yield onset | stress tensor | Newton its | von Mises vs scalar-q J2 |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (double ratio : {3.0, 4.0, 10.0, 15.0, 30.0})
      for (Dimension dim : kDims)
        for (const Hardening& h : kHardening)
          for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
            if ((ratio == 15.0 && dim != Dimension::ThreeD) || (ratio == 30.0 && dim == Dimension::ThreeD)) continue;
            const PathResult r = runPath(dim, ratio, path, h.K, h.H, 0.012, 120, norm);
            char sc[16] = "-";
            if (r.vmErrScalar >= 0) std::snprintf(sc, sizeof sc, "%.2f", 100 * r.vmErrScalar);
            std::printf("| %g | %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %d | %s |\n", ratio, dimName(dim), h.name,
                        pathName(path), 100 * r.vmErr, 100 * r.alphaErr, 100 * r.onsetErr, 100 * r.stressErr,
                        r.maxIterations, sc);
          }
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
// At the paper's delta/dx = 3, 4, 5 (whole volumes: up to 19 %, 3.7 %, see docs/materials.md) the bounds
// are the largest errors measured over the 12 cases of each ratio and dimension, rounded up by ~25 % (a
// regression guard, not a physical limit): von Mises / plastic strain / onset in %.
TEST(J2Equivalence, PartialVolumeFamilies) {
  struct Bound { double ratio; Dimension dim; double vm, other; };
  const Bound bounds[] = {{3, Dimension::ThreeD, 1.1, 0.75},     {3, Dimension::PlaneStrain, 1.9, 1.9},
                          {3, Dimension::PlaneStress, 3.1, 1.9},  {4, Dimension::ThreeD, 0.5, 0.35},
                          {4, Dimension::PlaneStrain, 0.8, 0.7},  {4, Dimension::PlaneStress, 2.9, 0.7},
                          {5, Dimension::ThreeD, 0.35, 0.2},     {5, Dimension::PlaneStrain, 0.5, 0.4},
                          {5, Dimension::PlaneStress, 2.8, 0.4},  {10, Dimension::ThreeD, 1.0, 1.0},
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
