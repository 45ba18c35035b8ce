// The OSB J2 models with a non-unit influence function (Peridigm's "Parabolic Decay" and "Gaussian") and
// the "Continuum" yield normalisation, against closed forms evaluated in this file.
//
// Reference: the model's trial state written out from its definition (Pirzadeh et al. 2024 Eqs. 4, 16,
// 31, 39-41; docs/materials.md), on the lattice family's geometry, with omega from its formula (below,
// not pf::influenceValue) and the moduli from E and nu:
//   m = sum omega x^2 V,  theta = k D/m sum omega x (e - e^dp) V,  t^d = (B/m) omega (e - c theta x - e^dp),
//   psi = |t^d|^2/2 + a2 (t^d . x)^2,  sigma_vm = sqrt(psi / Cy),  Cy = 5/(2 m_y) (3D), 4/(3 m_y) (2D),
//   a2 = 0 (3D), 5/(2 m_y) (2D); m_y = m (Discrete) or 4 pi delta^5/5, pi h delta^4/2 (Continuum).
// For omega = 1 on an isotropic family this is classical J2 (J2Equivalence); for omega != 1 the model's
// von Mises measure is that of classical J2 times sqrt(m2/m), m2 = sum omega^2 x^2 V (3D; the model, like
// Peridigm's, was written for omega = 1: docs/materials.md, limitation iii), which the tests pin down.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "J2PathRunner.hpp"

using namespace pftest;
using pf::Dimension;
using pf::Influence;

namespace {

constexpr double kPi = 3.14159265358979323846;

double omega(Influence::Kind kind, double r, double delta) {
  const double s = std::min(r, delta) / delta;
  if (kind == Influence::Gaussian) return std::exp(-s * s);                  // Peridigm's gaussian()
  if (kind == Influence::ParabolicDecay) return s < 0.5 ? 1.0 : 4.0 * s * (1.0 - s);  // parabolicDecay()
  return 1.0;
}

struct Reference {
  double m = 0, m2 = 0, vm = 0;
};

// sigma_vm of the centre of mp for the deformation F and plastic extension edp (null: none), from the
// formulas above on mp's family geometry (positions, volumes); norm = m_y of the yield constants (0: m).
Reference referenceVonMises(const pf::MaterialPoint& mp, Dimension dim, Influence::Kind kind, double ratio,
                            const std::array<double, 9>& F, const double* edp, double my = 0) {
  const pf::FamilyView& v = mp.view();
  const double delta = ratio * kDx;
  const double kappa = kE / (3 * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  double D = 3, k = 1, c = 1.0 / 3, B = 15 * mu;
  if (dim != Dimension::ThreeD) { D = 2; B = 8 * mu; c = 5.0 / 12; }
  if (dim == Dimension::PlaneStress) { k = (1 - 2 * kNu) / (1 - kNu); c = 1.0 / 3 + kappa / (8 * mu); }
  const bool betaOn = dim != Dimension::PlaneStrain;
  const int n = v.offsets[1] - v.offsets[0];
  std::vector<double> x(n), e(n), w(n), V(n), ep(n, 0.0);
  Reference r;
  for (int b = 0; b < n; ++b) {
    const int j = v.neighbors[b];
    double xi[3], y2 = 0, x2 = 0;
    for (int a = 0; a < 3; ++a) xi[a] = v.x[3 * j + a] - v.x[a];
    for (int a = 0; a < 3; ++a) {
      const double ya = F[3 * a] * xi[0] + F[3 * a + 1] * xi[1] + F[3 * a + 2] * xi[2];
      y2 += ya * ya; x2 += xi[a] * xi[a];
    }
    x[b] = std::sqrt(x2); e[b] = std::sqrt(y2) - x[b];
    w[b] = omega(kind, x[b], delta);
    V[b] = v.volume[j];
    if (edp) ep[b] = edp[b];
    r.m += w[b] * x2 * V[b];
    r.m2 += w[b] * w[b] * x2 * V[b];
  }
  double th = 0;
  for (int b = 0; b < n; ++b) th += w[b] * x[b] * (e[b] - (betaOn ? ep[b] : 0.0)) * V[b];
  th *= k * D / r.m;
  double S2 = 0, Sx = 0;
  for (int b = 0; b < n; ++b) {
    const double td = B / r.m * w[b] * (e[b] - c * th * x[b] - ep[b]);
    S2 += td * td * V[b]; Sx += td * x[b] * V[b];
  }
  if (my == 0) my = r.m;
  const double Cy = dim == Dimension::ThreeD ? 2.5 / my : 4.0 / (3.0 * my);
  const double a2 = dim == Dimension::ThreeD ? 0.0 : 2.5 / my;
  r.vm = std::sqrt((0.5 * S2 + a2 * Sx * Sx) / Cy);
  return r;
}

std::unique_ptr<pf::Material> j2(Dimension dim, double K, double H, const std::string& norm = "Discrete") {
  return pf::makeMaterial("Elastic Plastic Hardening", j2Values(dim, K, H), {{"Yield Normalization", norm}});
}

const Dimension kDims[] = {Dimension::ThreeD, Dimension::PlaneStrain, Dimension::PlaneStress};
const Influence::Kind kKinds[] = {Influence::One, Influence::ParabolicDecay, Influence::Gaussian};
const char* kindName(Influence::Kind k) { return k == Influence::One ? "One" : k == Influence::Gaussian ? "Gaussian" : "Parabolic Decay"; }

}  // namespace

// Below yield, with omega != 1: bit-identical to "Elastic" with the same omega, and the von Mises stress
// is the reference's (1e-10: round-off of ~10^3 bond sums; a wrong omega, dilatation or plane-stress
// factor, thickness or constant moves it by >= 1e-3).
TEST(PlasticInfluence, ElasticStateMatchesReference) {
  const double ratio = 4.3;
  for (Dimension dim : kDims)
    for (Influence::Kind kind : kKinds) {
      auto plastic = j2(dim, 20e9, 20e9);
      auto values = j2Values(dim, 0, 0);
      for (const char* p : {"Yield Stress", "Isotropic Hardening Modulus", "Kinematic Hardening Modulus"}) values.erase(p);
      auto elastic = pf::makeMaterial("Elastic", values);
      pf::MaterialPoint a(*plastic, kDx, ratio, kDx, false, Influence(kind)), b(*elastic, kDx, ratio, kDx, false, Influence(kind));
      const std::array<double, 9> F = {1 + 6e-4, 3e-4, 0, 3e-4, 1 - 2e-4, 0, 0, 0, dim == Dimension::ThreeD ? 1 + 1e-4 : 1.0};
      a.deform(F); b.deform(F); a.evaluate(); b.evaluate();
      SCOPED_TRACE(std::string(dimName(dim)) + " " + kindName(kind));
      ASSERT_EQ(a.value("Equivalent_Plastic_Strain"), 0.0);
      EXPECT_EQ(a.force(), b.force());
      const Reference r = referenceVonMises(a, dim, kind, ratio, F, nullptr);
      EXPECT_NEAR(a.value("Von_Mises_Stress"), r.vm, 1e-10 * r.vm);
      EXPECT_NEAR(a.weightedVolume(), r.m, 1e-12 * r.m);
    }
}

// Yield onset with omega != 1: the strain at which the model first yields (bisection) is where the
// reference von Mises equals sigma_y (to 1e-8: the bisection stops at 1e-12 of the strain), for uniaxial
// strain and shear; in 3D that strain is the classical one times sqrt(m/m2) (a closed form: for a
// homogeneous strain the deviatoric extension is x n.eps'.n whatever omega is), to 1 %: the lattice error
// of this ratio (measured 0.67 % for omega = 1 in uniaxial strain, see J2Equivalence).
TEST(PlasticInfluence, YieldOnsetIsTheReferences) {
  const double ratio = 6.3;
  for (Dimension dim : kDims)
    for (Influence::Kind kind : kKinds)
      for (Path path : {Path::Uniaxial, Path::Shear}) {
        auto mat = j2(dim, 20e9, 0);
        pf::MaterialPoint mp(*mat, kDx, ratio, kDx, false, Influence(kind));
        Reference r;
        const double s = firstYield([&](double a) {
          mp.deform(pathF(dim, pathTensor(path, a)));
          mp.evaluate();
          return mp.value("Equivalent_Plastic_Strain") > 0;
        }, 1e-3);
        r = referenceVonMises(mp, dim, kind, ratio, pathF(dim, pathTensor(path, s)), nullptr);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + kindName(kind) + " " + pathName(path));
        EXPECT_NEAR(r.vm, kSy, 1e-8 * kSy);
        if (dim == Dimension::ThreeD) {
          ClassicalJ2 cl(kE, kNu, kSy, 20e9, 0, ClassicalJ2::Mode::ThreeD);
          const double sc = firstYield([&](double a) { cl.update(pathTensor(path, a)); return cl.alphaT > 0; }, 1e-3);
          EXPECT_NEAR(s / sc, std::sqrt(r.m / r.m2), 0.01 * std::sqrt(r.m / r.m2));
        }
      }
}

// Plastic loading with omega != 1 (cyclic uniaxial strain to 1.2 %, iso / kin hardening): the state is
// plastic (alpha > 5e-3), and the reported von Mises (the return's, on the yield surface sigma_bar_n+1) equals the
// reference evaluated on the stored plastic extension to 1e-10 of sigma_y in every dimension for every omega
// (measured 2.4e-15 ... 4.4e-15: round-off of the bond sums). Since 2026-12-06 the plastic extension flows along
// t^d_tr / omega in 3D and plane strain (J2Flow::flowOverOmega), and in plane stress along t_perp / omega + phi pp x
// with t^d split along omega x (J2Flow::omegaSplit, OsbJ2OmegaSplit.hpp). With Eq. 52's flow along t^d the stored
// state was t^d_tr - (B/m) omega dlambda G t^d_tr, G t^d_tr only where omega = 1: gap 0.104 ... 0.232 sigma_y in 3D
// and plane strain, and in plane stress (x split, Eq. 52 with phi = 2) Parabolic Decay 0.185 / 0.231, Gaussian
// 0.290 / 0.311 (H = 0 / 20 GPa). Peridigm's elastic_plastic has Eq. 52's form.
TEST(PlasticInfluence, PlasticStateAgainstReference) {
  const double ratio = 6.3;
  for (Dimension dim : kDims)
    for (Influence::Kind kind : kKinds)
      for (double H : {0.0, 20e9}) {
        auto mat = j2(dim, 20e9 - H, H);
        pf::MaterialPoint mp(*mat, kDx, ratio, kDx, false, Influence(kind));
        double gap = 0, alphaMax = 0;
        for (int k = 1; k <= 60; ++k) {
          const auto F = pathF(dim, pathTensor(Path::Cyclic, pathStrain(Path::Cyclic, k, 60, 0.012)));
          mp.deform(F);
          mp.evaluate();
          const Reference r = referenceVonMises(mp, dim, kind, ratio, F, mp.state().trial("Deviatoric_Plastic_Extension"));
          gap = std::max(gap, std::fabs(r.vm - mp.value("Von_Mises_Stress")) / kSy);
          alphaMax = std::max(alphaMax, mp.value("Equivalent_Plastic_Strain"));
          mp.commit();
        }
        std::printf("%s %s H=%g: max |vm_reported - vm(stored state)| / sy = %.3e, alpha max %.4e\n", dimName(dim),
                    kindName(kind), H, gap, alphaMax);
        SCOPED_TRACE(std::string(dimName(dim)) + " " + kindName(kind) + " H = " + std::to_string(H));
        EXPECT_GT(alphaMax, 5e-3);
        EXPECT_LT(gap, 1e-10);
      }
}

// "Continuum" normalisation: the yield constants use m_y = 4 pi delta^5/5 (3D) or pi h delta^4/2 (2D)
// instead of the node's m. The von Mises stress of an elastic state is the reference's with that m_y
// (1e-10), and the model first yields where that reference reaches sigma_y (1e-8, bisection to 1e-12).
// In 3D (no (t.x)^2 term) that is a scaling: von Mises sqrt(m_y/m) times the Discrete one (1e-10) and
// the onset strain sqrt(m/m_y) times it (1e-4: the extension |F xi| - |xi| is not linear in the strain;
// measured 5e-6). A 6 % change of the constant moves either by 3 %.
TEST(PlasticInfluence, ContinuumNormalisationClosedForm) {
  const double ratio = 4.3, delta = ratio * kDx;
  for (Dimension dim : kDims) {
    const double my = dim == Dimension::ThreeD ? 0.8 * kPi * std::pow(delta, 5) : 0.5 * kPi * kDx * std::pow(delta, 4);
    auto cont = j2(dim, 20e9, 0, "Continuum"), disc = j2(dim, 20e9, 0, "Discrete");
    pf::MaterialPoint a(*cont, kDx, ratio, kDx), b(*disc, kDx, ratio, kDx);
    const auto F = pathF(dim, pathTensor(Path::Uniaxial, 1e-3));
    a.deform(F); b.deform(F); a.evaluate(); b.evaluate();
    SCOPED_TRACE(dimName(dim));
    const Reference r = referenceVonMises(a, dim, Influence::One, ratio, F, nullptr, my);
    EXPECT_NEAR(a.value("Von_Mises_Stress"), r.vm, 1e-10 * r.vm);
    const double ratioVm = a.value("Von_Mises_Stress") / b.value("Von_Mises_Stress");
    auto onset = [&](pf::MaterialPoint& mp) {
      return firstYield([&](double s) {
        mp.deform(pathF(dim, pathTensor(Path::Uniaxial, s)));
        mp.evaluate();
        return mp.value("Equivalent_Plastic_Strain") > 0;
      }, 1e-3);
    };
    const double sa = onset(a), sb = onset(b);
    const double vmAtOnset = referenceVonMises(a, dim, Influence::One, ratio, pathF(dim, pathTensor(Path::Uniaxial, sa)), nullptr, my).vm;
    EXPECT_NEAR(vmAtOnset, kSy, 1e-8 * kSy);
    if (dim == Dimension::ThreeD) {
      EXPECT_NEAR(ratioVm, std::sqrt(my / r.m), 1e-10);
      EXPECT_NEAR(sa / sb, std::sqrt(r.m / my), 1e-4);
    }
  }
}

// Information (docs/materials.md, limitation iii): plane stress with omega != 1 against classical plane-stress J2
// (ClassicalJ2) on the J2Equivalence paths (uniaxial, cyclic uniaxial, shear strain to 1.2 %; iso and kin hardening)
// at the ratio above. The return is consistent (PlasticStateAgainstReference), but the von Mises measure is written
// for omega = 1, so the model yields at another strain than J2 (YieldOnsetIsTheReferences) and its von Mises error
// follows. Asserted: each maximum over paths and hardening as measured, +-0.005 (the docs quote two decimals);
// omega = 1 is the lattice error of this small ratio (J2Equivalence holds it at 15 / 30).
TEST(PlasticInfluence, PlaneStressAgainstClassicalJ2) {
  const double ratio = 6.3;
  // measured max |vm - vm_J2| / sigma_y, |eps_y / eps_y,J2 - 1|, |alpha - alpha_J2| / max alpha_J2
  const double vmMeasured[] = {0.0403, 0.2093, 0.3201}, onsetMeasured[] = {0.0372, 0.1726, 0.3463},
               alphaMeasured[] = {0.0574, 0.2356, 0.4118};
  for (int i = 0; i < 3; ++i) {
    const Influence::Kind kind = kKinds[i];
    double vm = 0, onset = 0, alpha = 0;
    for (Path path : {Path::Uniaxial, Path::Cyclic, Path::Shear})
      for (double H : {0.0, 20e9}) {
        PathOptions o;
        o.influence = Influence(kind);
        const PathResult r = runPath(Dimension::PlaneStress, ratio, path, 20e9 - H, H, o);
        std::printf("%-15s %-9s H=%-6g vm %.4f alpha %.4f onset %.4f stress %.4f Newton %d\n", kindName(kind),
                    pathName(path), H, r.vmErr, r.alphaErr, r.onsetErr, r.stressErr, r.maxIterations);
        vm = std::max(vm, r.vmErr); onset = std::max(onset, r.onsetErr); alpha = std::max(alpha, r.alphaErr);
      }
    SCOPED_TRACE(kindName(kind));
    EXPECT_NEAR(vm, vmMeasured[i], 0.005);
    EXPECT_NEAR(onset, onsetMeasured[i], 0.005);
    EXPECT_NEAR(alpha, alphaMeasured[i], 0.005);
  }
}
