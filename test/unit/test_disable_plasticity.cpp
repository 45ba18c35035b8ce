// Peridigm's "Disable Plasticity" of Elastic Plastic (its BondBreakingInitialVelocity-EP deck: Yield Stress = 0
// with plasticity disabled, gold file equal to the Elastic deck's): the model is then the Elastic one, force and
// dilatation bit for bit, on a 5^3 lattice under a random deformation far past any yield; without the flag a
// zero yield stress is an input error naming the parameter.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "LatticeFixture.hpp"
#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

std::map<std::string, double> solid() {
  return {{"Density", 7800.0}, {"Bulk Modulus", 130e9}, {"Shear Modulus", 60e9}};
}

std::vector<double> forceOf(const pf::Material& m, const pftest::Lattice& L, const std::vector<double>& y,
                            std::vector<double>& theta) {
  pf::StateStore st;
  st.allocate(m.stateSpecs(), L.numNodes, L.fam.numBonds());
  std::vector<double> F(3 * L.numNodes, 0.0);
  m.computeForce(L.view(), y.data(), st, F.data());
  theta.assign(st.trial("Dilatation"), st.trial("Dilatation") + L.numNodes);
  return F;
}

}  // namespace

TEST(DisablePlasticity, IsTheElasticModel) {
  const pftest::Lattice L = pftest::makeLattice(5, false, 1e-3, 2.015, 0.0, pf::Influence::One, false);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> y(L.x);
  for (double& v : y) v += 5e-5 * u(rng);  // strains of order 5 %: far past any yield
  std::map<std::string, double> ep = solid();
  ep["Yield Stress"] = 0.0;
  ep["Disable Plasticity"] = 1.0;
  std::vector<double> thetaE, thetaP;
  const std::vector<double> fe = forceOf(*pf::makeMaterial("Elastic", solid()), L, y, thetaE);
  const std::vector<double> fp = forceOf(*pf::makeMaterial("Elastic Plastic", ep), L, y, thetaP);
  EXPECT_EQ(fe, fp);
  EXPECT_EQ(thetaE, thetaP);
}

TEST(DisablePlasticity, ZeroYieldStressNeedsIt) {
  std::map<std::string, double> ep = solid();
  ep["Yield Stress"] = 0.0;
  try {
    pf::makeMaterial("Elastic Plastic", ep);
    FAIL() << "Yield Stress = 0 with plasticity on was accepted";
  } catch (const pf::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Yield Stress' = 0"), std::string::npos) << e.what();
  }
  ep["Isotropic Hardening Modulus"] = 1e9;
  EXPECT_THROW(pf::makeMaterial("Elastic Plastic Hardening", ep), pf::InputError);
  ep.erase("Isotropic Hardening Modulus");
  ep["Disable Plasticity"] = 1.0;
  ep["Isotropic Hardening Modulus"] = 1e9;
  EXPECT_THROW(pf::makeMaterial("Elastic Plastic Hardening", ep), pf::InputError);  // Elastic Plastic's flag only
}
