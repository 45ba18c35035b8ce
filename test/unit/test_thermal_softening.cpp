// Johnson-Cook thermal softening of "Viscoplastic Correspondence" (materials/ViscoplasticCorrespondenceMaterial):
// the factor 1 - T*^q, T* = (T - T_r)/(T_m - T_r) clamped to [0, 1], against its closed form at and between the
// reference and melting temperatures, the Temperature read only when softening is asked for, and the flow stress
// of a plastic step scaled by the factor (fosterUpdate with the scaled yield against the unscaled one).
#include <gtest/gtest.h>

#include <cmath>

#include "core/InputError.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materials/FosterViscoplasticity.hpp"
#include "materials/ViscoplasticCorrespondenceMaterial.hpp"

namespace {

std::map<std::string, double> aluminium() {
  return {{"Density", 2700.0}, {"Young's Modulus", 68.9e9}, {"Poisson's Ratio", 0.333},
          {"Hourglass Coefficient", 0.0}, {"Yield Stress", 276e6}, {"Strain Hardening Exponent", 13.5},
          {"Rate Sensitivity Exponent", 44.0}, {"Reference Plastic Strain", 1e-3},
          {"Reference Plastic Strain Rate", 1e3}};
}

const pf::ViscoplasticCorrespondenceMaterial& cast(const std::unique_ptr<pf::Material>& m) {
  return dynamic_cast<const pf::ViscoplasticCorrespondenceMaterial&>(*m);
}

TEST(ThermalSoftening, FactorAgainstClosedForm) {
  auto v = aluminium();
  v["Melting Temperature"] = 925.0, v["Reference Temperature"] = 293.0, v["Thermal Softening Exponent"] = 2.0;
  const auto m = pf::makeMaterial("Viscoplastic Correspondence", v);
  const auto& vp = cast(m);
  EXPECT_EQ(vp.softening(250.0), 1.0);  // below T_r: no hardening from cold
  EXPECT_EQ(vp.softening(293.0), 1.0);
  EXPECT_NEAR(vp.softening(293.0 + 0.25 * 632.0), 1.0 - 0.0625, 1e-15);
  EXPECT_NEAR(vp.softening(293.0 + 0.5 * 632.0), 0.75, 1e-15);
  EXPECT_EQ(vp.softening(925.0), 0.0);
  EXPECT_EQ(vp.softening(2000.0), 0.0);  // molten: no strength, never negative
  const std::vector<std::string> read = m->fieldsRead();
  EXPECT_NE(std::find(read.begin(), read.end(), "Temperature"), read.end());
}

TEST(ThermalSoftening, NoneWithoutItsParameters) {
  const auto m = pf::makeMaterial("Viscoplastic Correspondence", aluminium());
  EXPECT_EQ(cast(m).softening(900.0), 1.0);
  EXPECT_TRUE(m->fieldsRead().empty());
}

TEST(ThermalSoftening, PartialParametersAreAnInputError) {
  auto v = aluminium();
  v["Melting Temperature"] = 925.0;
  EXPECT_THROW(pf::makeMaterial("Viscoplastic Correspondence", v), pf::InputError);
  v["Reference Temperature"] = 1000.0, v["Thermal Softening Exponent"] = 1.0;  // T_m below T_r
  EXPECT_THROW(pf::makeMaterial("Viscoplastic Correspondence", v), pf::InputError);
}

// A plastic step's deviatoric stress lies on the flow surface sqrt(2/3) G: with the yield scaled by the factor the
// returned von Mises stress scales by it too (the rate factor is the same function of the same dlambda / (dt rate_0)
// only when the factor is applied to the whole G, as Johnson-Cook's multiplicative form does).
TEST(ThermalSoftening, ScaledYieldScalesTheReturnedStress) {
  const pf::FosterLaw law{276e6, 13.5, 44.0, 1e-3, 1e3};
  const double K = 68.9e9 / (3 * (1 - 2 * 0.333)), mu = 68.9e9 / (2 * 1.333);
  pf::Mat3 de{};
  de[0] = 0.02, de[4] = -0.01, de[8] = -0.01;  // far past yield in one step
  const pf::Mat3 zero{};
  pf::FosterLaw soft = law;
  soft.yield *= 0.5;
  const pf::FosterStep a = pf::fosterUpdate(law, K, mu, zero, 0.0, de, 1e-6);
  const pf::FosterStep b = pf::fosterUpdate(soft, K, mu, zero, 0.0, de, 1e-6);
  auto vm = [](const pf::Mat3& t) {
    const pf::Mat3 s = pf::deviator(t);
    return std::sqrt(1.5 * pf::ddot(s, s));
  };
  EXPECT_GT(b.epsP, a.epsP);  // more plastic flow at the lower flow stress
  // G = Y (1+eps/eps0)^(1/n) (1+rate/rate0)^(1/m): the rate terms differ (b flows more), so compare each with G.
  const double ga = law.yield * std::pow(1 + a.rate / law.rate0, 1 / law.m);
  const double gb = soft.yield * std::pow(1 + b.rate / soft.rate0, 1 / soft.m);
  EXPECT_NEAR(vm(a.tau) / ga, 1.0, 1e-10);
  EXPECT_NEAR(vm(b.tau) / gb, 1.0, 1e-10);
}

}  // namespace
