// Material-point equivalence of the OSB J2 models with classical small-strain J2 (Simo & Hughes),
// at one interior lattice point with a complete family.
#include <gtest/gtest.h>

#include <cstdio>
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
// 1 % (3D, plane strain); 2 % in plane stress, 2.5 % for plane-stress cyclic paths with kinematic
// hardening. sigma_y is the scale because the stress error of a lattice point is an elastic-stiffness
// error (the grid's anisotropic fourth moment, design doc) times the stress swing, up to 2 sigma_bar on
// a cycle. That error reaches 1 % only at delta/dx = 15 (3D) and 30 (2D, whose lattice error oscillates
// with delta/dx: 12 is good, 15 is bad); the return mapping itself is exact to round-off in 3D and plane
// strain (radial). The extra plane-stress margin: uniaxial strain in plane stress is non-proportional
// in stress space, where a scalar back stress cannot follow the classical tensor one.
TEST(J2Equivalence, MatchesClassicalJ2) {
  for (Dimension dim : kDims) {
    const double ratio = dim == Dimension::ThreeD ? 15.0 : 30.0;
    for (const Hardening& h : kHardening)
      for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
        double tol = dim == Dimension::PlaneStress ? 0.02 : 0.01;
        if (dim == Dimension::PlaneStress && path == Path::Cyclic && h.H > 0) tol = 0.025;
        const PathResult r = runPath(dim, ratio, path, h.K, h.H);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + h.name + " " + pathName(path));
        EXPECT_LT(r.vmErr, tol);
        EXPECT_LT(r.alphaErr, tol);
        EXPECT_LT(r.onsetErr, tol);
        EXPECT_LE(r.maxIterations, 10);
      }
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

// Error table (model x dimension x path) at delta/dx = 3, 4, 10 (and 15 in 3D, 30 in 2D) for
// docs/materials.md, for both yield normalisations.
TEST(J2Equivalence, ErrorTable) {
  for (const char* norm : {"Discrete", "Continuum"}) {
    std::printf("\nYield Normalization = %s: max |vm - vm_J2|/sy, max |alpha - alpha_J2|/max alpha_J2, "
                "onset, max in-plane stress component error/sy (%%)\n", norm);
    std::printf("| ratio | dim | hardening | path | von Mises | eq. plastic strain | yield onset | stress tensor | Newton its |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (double ratio : {3.0, 4.0, 10.0, 15.0, 30.0})
      for (Dimension dim : kDims)
        for (const Hardening& h : kHardening)
          for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear}) {
            if ((ratio == 15.0 && dim != Dimension::ThreeD) || (ratio == 30.0 && dim == Dimension::ThreeD)) continue;
            const PathResult r = runPath(dim, ratio, path, h.K, h.H, 0.012, 120, norm);
            std::printf("| %g | %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %d |\n", ratio, dimName(dim), h.name,
                        pathName(path), 100 * r.vmErr, 100 * r.alphaErr, 100 * r.onsetErr, 100 * r.stressErr,
                        r.maxIterations);
          }
  }
  std::fflush(stdout);
}
