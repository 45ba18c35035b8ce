// Peridigm's "Elastic Plastic Hardening" (Hardening Modulus = Peridigm's H) and its shear correction factor,
// against references written here: a classical integration of Peridigm's law over one lattice point's family
// (bisection for dlambda instead of Peridigm's closed-form cubic), and the factor's lattice sums.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "J2PathRunner.hpp"
#include "LatticeFixture.hpp"
#include "materials/PeridigmHardening.hpp"

using namespace pftest;
using pf::Dimension;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::map<std::string, double> peridigmValues(double H, bool scf = false) {
  auto v = j2Values(Dimension::ThreeD, 0, 0);
  v.erase("Isotropic Hardening Modulus");
  v.erase("Kinematic Hardening Modulus");
  v["Apply Shear Correction Factor"] = scf ? 1.0 : 0.0;
  v["Hardening Modulus"] = H;
  return v;
}

// Peridigm's law (elastic_plastic_hardening.cxx) integrated bond by bond, with the consistency condition
// |t^d_tr|^2 / (2 (1 + alpha dl)^2) = psi0 + H (lambda_n + dl) solved by bisection.
struct PeridigmLawReference {
  struct Bond { double xi[3], x, V; int j; };
  std::vector<Bond> bonds;
  std::vector<double> edp;
  double m, alpha, bulk, psi0, H, V0, lambda = 0.0;

  // s: the shear correction factor (1 = off), applied as Peridigm applies it: alpha = s 15 mu / m, s^2 psi0.
  PeridigmLawReference(const pf::MaterialPoint& mp, double horizon, double H_, double s = 1.0) : H(H_) {
    const pf::FamilyView& f = mp.view();
    for (int b = f.offsets[0]; b < f.offsets[1]; ++b) {
      Bond bd{};
      bd.j = f.neighbors[b];
      for (int c = 0; c < 3; ++c) bd.xi[c] = f.x[3 * bd.j + c] - f.x[c];
      bd.x = std::sqrt(bd.xi[0] * bd.xi[0] + bd.xi[1] * bd.xi[1] + bd.xi[2] * bd.xi[2]);
      bd.V = f.volume[bd.j];
      bonds.push_back(bd);
    }
    edp.assign(bonds.size(), 0.0);
    m = 0.0;
    for (const Bond& b : bonds) m += b.x * b.x * b.V;
    const double mu = kE / (2 * (1 + kNu));
    bulk = kE / (3 * (1 - 2 * kNu));
    alpha = s * 15.0 * mu / m;
    psi0 = s * s * 25.0 * kSy * kSy / (8.0 * kPi * std::pow(horizon, 5));  // Peridigm's 3D yield value
    V0 = mp.nodeVolume();
  }

  double deltaLambda(double S) const {
    auto g = [&](double dl) { return S / (2 * (1 + alpha * dl) * (1 + alpha * dl)) - psi0 - H * (lambda + dl); };
    if (!(g(0.0) > 0.0)) return 0.0;
    double lo = 0.0, hi = (std::sqrt(S / (2 * psi0)) - 1) / alpha;  // g(hi) = -H (lambda + hi) < 0
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  // One load step at y = F X from the committed state; returns the force density each neighbour receives.
  std::vector<double> step(const std::array<double, 9>& F) {
    std::vector<double> e(bonds.size()), td(bonds.size()), y(3 * bonds.size());
    double theta = 0.0;
    for (std::size_t b = 0; b < bonds.size(); ++b) {
      double len = 0.0;
      for (int a = 0; a < 3; ++a) {
        y[3 * b + a] = F[3 * a] * bonds[b].xi[0] + F[3 * a + 1] * bonds[b].xi[1] + F[3 * a + 2] * bonds[b].xi[2];
        len += y[3 * b + a] * y[3 * b + a];
      }
      e[b] = std::sqrt(len) - bonds[b].x;
      theta += 3.0 * bonds[b].x * e[b] * bonds[b].V / m;
    }
    double S = 0.0;
    for (std::size_t b = 0; b < bonds.size(); ++b) {
      td[b] = alpha * (e[b] - theta * bonds[b].x / 3.0 - edp[b]);
      S += td[b] * td[b] * bonds[b].V;
    }
    const double dl = deltaLambda(S);
    lambda += dl;
    std::vector<double> f(3 * bonds.size());
    for (std::size_t b = 0; b < bonds.size(); ++b) {
      td[b] /= 1 + alpha * dl;
      edp[b] += dl * td[b];
      const double t = 3.0 * bulk * theta * bonds[b].x / m + td[b];
      const double len = bonds[b].x + e[b];
      for (int a = 0; a < 3; ++a) f[3 * b + a] = -t * y[3 * b + a] / len * V0;
    }
    return f;
  }
};

}  // namespace

// Cyclic uniaxial strain (+-1.2 %) on an interior 3D point, delta/dx = 3 as in Peridigm's decks: force on
// every neighbour and Lambda after each committed step against the reference integration, without and with
// the shear correction factor (s from the model: its own value is checked in ShearCorrectionFactorOnALattice).
TEST(PeridigmHardening, MatchesClassicalIntegrationOfPeridigmsLaw) {
  const double ratio = 3.0, horizon = ratio * kDx;
  for (bool scf : {false, true}) {
    // H of the order of psi0 alpha (psi0 per unit alpha lambda, a dimensionless plastic measure): the yield
    // value doubles at alpha lambda = 2. Peridigm's closed-form cubic is well conditioned in this range.
    auto probe = pf::makeMaterial("Elastic Plastic Hardening", peridigmValues(0.0));
    pf::MaterialPoint p0(*probe, kDx, ratio, kDx);
    PeridigmLawReference ref0(p0, horizon, 0.0);
    const double H = 0.5 * ref0.psi0 * ref0.alpha;
    auto mat = pf::makeMaterial("Elastic Plastic Hardening", peridigmValues(H, scf));
    pf::MaterialPoint mp(*mat, kDx, ratio, kDx);
    mp.deform({1, 0, 0, 0, 1, 0, 0, 0, 1});
    mp.evaluate();  // sets the factor
    const double s = mp.value("Surface_Correction_Factor");
    EXPECT_EQ(s == 1.0, !scf);
    PeridigmLawReference ref(mp, horizon, H, s);
    const int steps = 120;
    int plastic = 0;
    double worst = 0.0, worstLambda = 0.0, lambdaPrev = 0.0;
    for (int k = 1; k <= steps; ++k) {
      const double e = pathStrain(Path::Cyclic, k, steps, 0.012);
      const std::array<double, 9> F = {1 + e, 0, 0, 0, 1, 0, 0, 0, 1};
      mp.deform(F);
      mp.evaluate();
      const std::vector<double> f = ref.step(F);
      double fmax = 0.0, diff = 0.0;
      for (std::size_t b = 0; b < ref.bonds.size(); ++b)
        for (int a = 0; a < 3; ++a) {
          fmax = std::max(fmax, std::fabs(f[3 * b + a]));
          diff = std::max(diff, std::fabs(mp.force()[3 * ref.bonds[b].j + a] - f[3 * b + a]));
        }
      worst = std::max(worst, diff / fmax);
      worstLambda = std::max(worstLambda, std::fabs(mp.value("Lambda") - ref.lambda) / std::max(ref.lambda, 1e-300));
      if (ref.lambda > lambdaPrev) ++plastic;
      lambdaPrev = ref.lambda;
      mp.commit();
    }
    std::printf("Peridigm law vs reference (s = %.6f): %d plastic steps, alpha lambda = %.3f, max |df|/|f| = "
                "%.2e, max |dlambda|/lambda = %.2e\n", s, plastic, ref.alpha * ref.lambda, worst, worstLambda);
    EXPECT_GT(plastic, 40);                  // yields in tension, compression and tension again
    EXPECT_GT(ref.alpha * ref.lambda, 0.5);  // hardening matters: H lambda > psi0 / 4
    // Closed-form cubic (Peridigm's trigonometric/Cardano roots) vs bisection to the last bit: the closed
    // form loses digits to cancellation between its a/3 and root terms (measured 4e-15 in force, 9e-14 in
    // lambda); 1e-11 leaves two orders for other compilers/ISAs and still fails any error in the law itself.
    EXPECT_LT(worst, 1e-11);
    EXPECT_LT(worstLambda, 1e-11);
  }
}

// The closed-form cubic against its defining equation, across the branches Peridigm takes (three real roots
// or one) and H -> 0 (Peridigm's perfectly plastic dlambda, elastic_plastic.cxx).
TEST(PeridigmHardening, DeltaLambdaSatisfiesConsistency) {
  const double alpha = 2.0, psi0 = 3.0;
  for (double H : {0.0, 0.3, 3.0, 30.0})
    for (double lambdaN : {0.0, 0.5})
      for (double over : {1.01, 1.5, 4.0}) {  // |t|^2 / 2 over the current yield value
        const double S = 2.0 * over * (psi0 + H * lambdaN);
        const double dl = pf::peridigmDeltaLambda(std::sqrt(S), lambdaN, psi0, alpha, H);
        const double g = S / (2 * (1 + alpha * dl) * (1 + alpha * dl)) - psi0 - H * (lambdaN + dl);
        EXPECT_GT(dl, 0.0);
        EXPECT_LT(std::fabs(g), 1e-12 * S) << "H " << H << " lambdaN " << lambdaN << " over " << over;
      }
  // Inside the hardened surface (above psi0, below psi0 + H lambda_n): elastic, as in Peridigm.
  EXPECT_EQ(pf::peridigmDeltaLambda(std::sqrt(2 * 4.0), 1.0, 3.0, 2.0, 3.0), 0.0);
}

// The H = 2e10 on the benchmark cubes (steel, delta = 3.015 mm: psi0 = 1.44e30, alpha = 1.63e24 at
// m = 1.131 of the sphere's; s = 1.37 near a face): psi0 / H = 7e19 swamps the cubic's small root, and the
// closed form returns rounding noise -- here a spurious alpha dl ~ 1e36 (elsewhere 0). peridigmDeltaLambda
// then solves the same consistency condition by Newton: H lambda is negligible, so the root is the perfectly
// plastic one to ~H/(psi0 alpha).
TEST(PeridigmHardening, IllConditionedCubicFallsBackToNewton) {
  const double mu = kE / (2 * (1 + kNu)), delta = 3.015e-3, s = 1.37, H = 2e10;
  const double psi0 = s * s * 25.0 * kSy * kSy / (8.0 * kPi * std::pow(delta, 5));
  const double alpha = s * 15.0 * mu / (1.131 * 0.8 * kPi * std::pow(delta, 5));
  const double S = 2.0 * 1.1 * psi0;  // 10 % over the yield value
  auto g = [&](double dl) { return S / (2 * (1 + alpha * dl) * (1 + alpha * dl)) - psi0 - H * dl; };
  const double closed = pf::peridigmCubicRoot(std::sqrt(S), 0.0, psi0, alpha, H);
  const double dl = pf::peridigmDeltaLambda(std::sqrt(S), 0.0, psi0, alpha, H);
  const double perfect = (std::sqrt(S / (2 * psi0)) - 1) / alpha;
  std::printf("H = 2e10: closed form alpha dl = %.3e (g = %.2e of |t|^2/2), Newton alpha dl = %.6e, "
              "perfectly plastic %.6e\n", alpha * closed, g(closed) / (S / 2), alpha * dl, alpha * perfect);
  EXPECT_GT(std::fabs(g(closed)), 1e-3 * S / 2);  // the closed form is noise here (if this fails, it improved)
  EXPECT_LT(std::fabs(g(dl)), 1e-12 * S / 2);     // Newton to round-off of the terms of g
  EXPECT_NEAR(dl, perfect, 1e-12 * perfect);      // H dl / psi0 ~ 1e-44: the perfectly plastic root
}

// Peridigm's factor (material_utilities.cxx, inverted by Peridigm_ElasticPlasticHardeningMaterial.cpp) is
// s = D / D_sphere: the family's deviatoric response to pure shear over the continuum sphere's 4 gamma^2 m/15.
// Checked here against the first-order lattice sum, and its effect: it multiplies the elastic shear
// stress by s, so the lattice's shear stress over the classical 2 mu eps_xy goes from s to s^2.
TEST(PeridigmHardening, ShearCorrectionFactorOnALattice) {
  const double ratio = 3.0;
  auto v = peridigmValues(0.0);
  v["Yield Stress"] = 1e15;  // elastic
  auto off = pf::makeMaterial("Elastic Plastic Hardening", v);
  v["Apply Shear Correction Factor"] = 1.0;
  auto on = pf::makeMaterial("Elastic Plastic Hardening", v);
  pf::MaterialPoint a(*on, kDx, ratio, kDx), b(*off, kDx, ratio, kDx);
  const double g = 1e-4;  // eps_xy = g (Peridigm's set_pure_shear: du_x/dy = du_y/dx = g)
  const std::array<double, 9> F = {1, g, 0, g, 1, 0, 0, 0, 1};
  a.deform(F); b.deform(F);
  a.evaluate(); b.evaluate();
  // First-order lattice sum: e = 2 g xi_x xi_y / |xi| (theta = 0 by symmetry), D / D_sphere per mode.
  const pf::FamilyView& f = a.view();
  double D[3] = {0, 0, 0};
  const int planes[3][2] = {{0, 1}, {2, 0}, {1, 2}};
  for (int k = f.offsets[0]; k < f.offsets[1]; ++k) {
    const int j = f.neighbors[k];
    const double* xi = f.x + 3 * j;  // the centre is at the origin
    const double x2 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    for (int p = 0; p < 3; ++p) D[p] += 4.0 * xi[planes[p][0]] * xi[planes[p][0]] * xi[planes[p][1]] * xi[planes[p][1]] / x2 * f.volume[j];
  }
  const double sRef = std::max({D[0], D[1], D[2]}) / (4.0 * a.weightedVolume() / 15.0);
  const double s = a.value("Surface_Correction_Factor");
  const double mu = kE / (2 * (1 + kNu));
  const double ratioOn = a.stress()[1] / (2 * mu * g), ratioOff = b.stress()[1] / (2 * mu * g);
  std::printf("delta/dx = 3: s = %.6f (lattice sum %.6f); sigma_xy / (2 mu eps_xy) = %.6f without, %.6f with\n", s,
              sRef, ratioOff, ratioOn);
  EXPECT_EQ(b.value("Surface_Correction_Factor"), 1.0);
  // Peridigm's probe uses gamma = 1e-6 and exact lengths: O(gamma) from the first-order sum.
  EXPECT_NEAR(s, sRef, 1e-5 * sRef);
  // g = 1e-4 against first order: O(g) relative.
  EXPECT_NEAR(ratioOff, s, 1e-3 * s);
  EXPECT_NEAR(ratioOn, s * s, 1e-3 * s * s);
  // The deviatoric term is scaled by s exactly; the isotropic one (theta = O(g^2) on the symmetric lattice)
  // is not, which leaves a relative O(g) difference (measured 7e-11).
  EXPECT_NEAR(a.stress()[1] / b.stress()[1], s, 1e-9 * s);
}

// The stiffness bound scaled by max(1, s_i) (ElasticPlasticMaterial::stiffnessBound) bounds the force
// Jacobian's row sums, by central differences column by column, on a 7^3 cube: every node lies within a
// horizon of a face, where s varies most (neighbours' s_j differ from s_i) and the factor also changes
// the dilatation coupling (A - s B c).
TEST(PeridigmHardening, StiffnessBoundWithShearCorrection) {
  for (bool scf : {false, true}) {
    const Lattice L = makeLattice(7, false, kDx, 3.015, kDx, pf::Influence::One, false);
    auto v = peridigmValues(0.0, scf);
    v["Yield Stress"] = 1e15;  // elastic
    auto mat = pf::makeMaterial("Elastic Plastic Hardening", v);
    std::vector<double> bound(L.numNodes, 0.0);
    mat->stiffnessBound(L.view(), bound.data());
    auto force = [&](const std::vector<double>& y) {
      pf::StateStore st;
      st.allocate(mat->stateSpecs(), L.numQueries, L.fam.numBonds());
      std::vector<double> f(3 * L.numNodes, 0.0);
      mat->computeForce(L.view(), y.data(), st, f.data());
      return f;
    };
    std::vector<double> y(L.x);
    for (std::size_t k = 0; k < y.size(); ++k) y[k] += 1e-4 * kDx * std::sin(1.7 * k + 0.3);  // small, generic
    const double h = 1e-7 * kDx;  // FD error ~ eps |xi| / h ~ 2e-9 relative (see test_elastic_osb.cpp)
    std::vector<double> row(3 * L.numNodes, 0.0);
    for (std::size_t c = 0; c < y.size(); ++c) {
      const double y0 = y[c];
      y[c] = y0 + h;
      const std::vector<double> fp = force(y);
      y[c] = y0 - h;
      const std::vector<double> fm = force(y);
      y[c] = y0;
      for (std::size_t k = 0; k < row.size(); ++k) row[k] += std::fabs((fp[k] - fm[k]) / (2 * h));
    }
    double worst = 0.0;
    for (int i = 0; i < L.numNodes; ++i)
      for (int a = 0; a < 3; ++a) worst = std::max(worst, row[3 * i + a] / bound[i]);
    std::printf("7^3 cube, factor %s: max row sum / bound = %.4f\n", scf ? "on" : "off", worst);
    EXPECT_LE(worst, 1.0);  // a bound: no allowance (the FD error is ~1e-8)
  }
}
