// Unit tests of "Elastic Bond Based" (materials/ElasticBondBasedMaterial: Peridigm's bond-based elastic solid, the
// Microelastic kernels with Peridigm's micromodulus) against closed forms:
//  1. the micromodulus is Peridigm's (elastic_bond_based.cxx): 18K/(pi delta^4) in 3D, 12K/(pi h delta^3) in
//     plane stress and plane strain (h = Height), K from E with nu = 1/4 or 1/3;
//  2. a 2D isotropic in-plane stretch stores W = 2K eps^2, the energy of a plate whose in-plane bulk modulus is K;
//  3. the discretization's influence function is ignored (omega = 1), as Peridigm's;
//  4. its input rules (Height, no Poisson's ratio).
// Units: SI; K = 100 GPa, dx = 1 mm, h = 2 mm in 2D.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "BondBasedValues.hpp"
#include "LatticeFixture.hpp"
#include "test_input_helpers.hpp"
#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/ElasticBondBasedMaterial.hpp"

namespace {

using pf::Dimension;
constexpr double kK = 100e9, kDx = 1e-3, kH = 2e-3, kPi = 3.14159265358979323846;
const Dimension kDims[3] = {Dimension::ThreeD, Dimension::PlaneStress, Dimension::PlaneStrain};

std::map<std::string, double> values(Dimension dim) { return pftest::bondBasedValues(dim, kK, kH, "Height"); }

const pf::MicroelasticMaterial& bb(const pf::Material& m) { return dynamic_cast<const pf::MicroelasticMaterial&>(m); }

pftest::Lattice lattice(Dimension dim, pf::Influence infl) {
  return pftest::makeLattice(9, dim != Dimension::ThreeD, kDx, 3.5, kH, infl, /*centreOnly=*/true);
}

// The centre's stored energy density under y = (1 + eps) x in the model's plane (every direction in 3D).
double stretchEnergy(const pf::Material& mat, const pftest::Lattice& L, double eps, std::vector<double>* force) {
  std::vector<double> y = L.x;
  for (int p = 0; p < L.numNodes; ++p)
    for (int a = 0; a < (L.planar ? 2 : 3); ++a) y[3 * p + a] *= 1 + eps;
  pf::StateStore st;
  st.allocate(mat.stateSpecs(), L.numQueries, L.fam.numBonds());
  std::vector<double> F(3 * L.numNodes, 0.0);
  mat.enableOutput("Stored_Elastic_Energy");
  mat.computeForce(L.view(), y.data(), st, F.data());
  if (force) *force = F;
  return st.trial("Stored_Elastic_Energy")[0] / L.volume[0];
}

}  // namespace

// 1. Same formula, other arithmetic order: round-off only (1e-14). A deck's E gives K = E/(3(1 - 2 nu)).
TEST(ElasticBondBased, MicromodulusIsPeridigms) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(pf::toString(dim));
    const auto L = lattice(dim, pf::Influence::One);
    const double d = L.horizon;
    const double cRef = dim == Dimension::ThreeD ? 18 * kK / (kPi * std::pow(d, 4)) : 12 * kK / (kPi * kH * std::pow(d, 3));
    auto mat = pf::makeMaterial("Elastic Bond Based", values(dim));
    EXPECT_NEAR(bb(*mat).micromodulus(L.view(), 0) / cRef, 1.0, 1e-14);
    auto v = values(dim);
    v.erase("Bulk Modulus");
    const double nu = dim == Dimension::PlaneStress ? 1.0 / 3.0 : 0.25;
    v["Young's Modulus"] = 3 * kK * (1 - 2 * nu);
    EXPECT_NEAR(bb(*pf::makeMaterial("Elastic Bond Based", v)).micromodulus(L.view(), 0) / cRef, 1.0, 1e-14);
  }
}

// 2. Every bond of the centre has s = eps, so W = (c/4) eps^2 sum |xi| V_j; with Peridigm's 2D c this is
//    2K eps^2 (sum / Q), Q = 2 pi h delta^3 / 3: W/(2K eps^2) - 1 equals the lattice's quadrature error of Q
//    to round-off (cancellation in s: 1e-13 relative, twice). Microelastic's plane-stress calibration would be
//    off by a factor 3/4, its plane-strain one by 6/5.
TEST(ElasticBondBased, PlanarStretchHasInPlaneBulkModulusK) {
  const double eps = 1e-3;
  for (Dimension dim : {Dimension::PlaneStress, Dimension::PlaneStrain}) {
    SCOPED_TRACE(pf::toString(dim));
    const auto L = lattice(dim, pf::Influence::One);
    auto mat = pf::makeMaterial("Elastic Bond Based", values(dim));
    const double W = stretchEnergy(*mat, L, eps, nullptr);
    double b = 0.0;
    for (int k = L.fam.offsets[0]; k < L.fam.offsets[1]; ++k) b += L.fam.refLength[k] * L.volume[L.fam.neighbors[k]];
    const double Q = 2 * kPi * kH * std::pow(L.horizon, 3) / 3;
    EXPECT_NEAR(W / (2 * kK * eps * eps) - 1, b / Q - 1, 1e-12);
  }
}

// 3. Peridigm's kernel has no influence function: a Gaussian one on the discretization changes no force (exactly:
//    the same arithmetic).
TEST(ElasticBondBased, IgnoresTheInfluenceFunction) {
  for (Dimension dim : kDims) {
    SCOPED_TRACE(pf::toString(dim));
    std::vector<double> F[2];
    for (int g = 0; g < 2; ++g) {
      auto L = lattice(dim, g ? pf::Influence::Gaussian : pf::Influence::One);
      L.fam.unitInfluence = g == 0;
      auto mat = pf::makeMaterial("Elastic Bond Based", values(dim));
      stretchEnergy(*mat, L, 1e-3, &F[g]);
    }
    ASSERT_EQ(F[0].size(), F[1].size());
    double largest = 0.0;
    for (std::size_t k = 0; k < F[0].size(); ++k) {
      EXPECT_EQ(F[0][k], F[1][k]) << "component " << k;
      largest = std::max(largest, std::fabs(F[0][k]));
    }
    EXPECT_GT(largest, 0.0);  // the stretch loads the bonds
  }
}

TEST(ElasticBondBased, InputRules) {
  auto v = values(Dimension::ThreeD);
  v["Poisson's Ratio"] = 0.25;  // Peridigm refuses any, the model's own value included
  EXPECT_INPUT_ERROR(pf::makeMaterial("Elastic Bond Based", v), "(material point)", "Poisson's Ratio");
  v = values(Dimension::ThreeD);
  v["Young's Modulus"] = 150e9;  // K and E: one constant too many
  EXPECT_INPUT_ERROR(pf::makeMaterial("Elastic Bond Based", v), "(material point)", "Young's Modulus");
  auto ps = values(Dimension::PlaneStress);
  ps.erase("Height");
  EXPECT_INPUT_ERROR(pf::makeMaterial("Elastic Bond Based", ps), "(material point)", "Height");
  ps["Thickness"] = kH;  // Peridigm's name for this model is Height
  EXPECT_INPUT_ERROR(pf::makeMaterial("Elastic Bond Based", ps), "(material point)", "Thickness");
  v = values(Dimension::ThreeD);
  v["Height"] = kH;  // only for a 2D model
  EXPECT_INPUT_ERROR(pf::makeMaterial("Elastic Bond Based", v), "(material point)", "Height");
}
