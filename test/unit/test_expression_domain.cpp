// Issue 15 part 2: an argument outside a function's domain gives NaN and a reason, never an abort of
// the process (Pamgen's own sqrt, log, log10, asin and acos assert). Values inside the domain are the
// C library's, bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Expression.hpp"
#include "core/InfluenceFunction.hpp"
#include "core/InputError.hpp"

namespace {

TEST(ExpressionDomain, OutOfDomainIsNanWithTheCall) {
  const pf::Expression e("sqrt(x) + log(y) + log10(z) + asin(t) + acos(t)", "ctx");
  EXPECT_EQ(e(4.0, std::exp(1.0), 100.0, 0.5), 2.0 + 1.0 + 2.0 + std::asin(0.5) + std::acos(0.5));
  EXPECT_EQ(e.whyNotFinite(4.0, 1.0, 1.0, 0.5), "");
  EXPECT_TRUE(std::isnan(e(-0.25, 1.0, 1.0, 0.0)));
  EXPECT_EQ(e.whyNotFinite(-0.25, 1.0, 1.0, 0.0), "sqrt(-0.25) is undefined");
  EXPECT_EQ(e.whyNotFinite(1.0, -2.0, 1.0, 0.0), "log(-2) is undefined");
  EXPECT_EQ(e.whyNotFinite(1.0, 1.0, -3.0, 0.0), "log10(-3) is undefined");
  EXPECT_EQ(e.whyNotFinite(1.0, 1.0, 1.0, 1.5), "asin(1.5) is undefined");  // the first failing call
  const pf::Expression a("acos(t)", "ctx");
  EXPECT_EQ(a.whyNotFinite(0, 0, 0, -1.0000001), "acos(-1.0000001) is undefined");
}

TEST(ExpressionDomain, ArithmeticNonFiniteHasNoDomainReason) {
  const pf::Expression e("1.0/(t-t)", "ctx");
  EXPECT_TRUE(std::isinf(e(0, 0, 0, 1.0)));
  EXPECT_EQ(e.whyNotFinite(0, 0, 0, 1.0), "");
  const pf::Expression z("log(t)", "ctx");  // log(0) = -inf is in the domain's closure: the caller's check
  EXPECT_EQ(z(0, 0, 0, 0.0), -INFINITY);
}

TEST(ExpressionDomain, ReasonDoesNotLeakToTheNextEvaluation) {
  const pf::Expression bad("sqrt(t)", "ctx"), good("t", "ctx");
  bad(0, 0, 0, -1.0);
  EXPECT_EQ(good.whyNotFinite(0, 0, 0, 1.0), "");
  EXPECT_EQ(bad.whyNotFinite(0, 0, 0, 1.0), "");
}

TEST(ExpressionDomain, ConstantCallsAndRefusedFunctionsFailAtInput) {
  EXPECT_THROW(pf::Expression("sqrt(-1.0)*t", "ctx"), pf::InputError);
  for (const char* text : {"printf(t)", "rand()*t", "drand()", "readline(t, t)", "value = scanf(t)"}) {
    try {
      pf::Expression e(text, "in.xml: Boundary Conditions/B/Value");
      ADD_FAILURE() << text << " was accepted";
    } catch (const pf::InputError& err) {
      EXPECT_NE(std::string(err.what()).find("is not available in expressions"), std::string::npos) << err.what();
      EXPECT_NE(std::string(err.what()).find("in.xml: Boundary Conditions/B/Value"), std::string::npos);
    }
  }
}

TEST(ExpressionDomain, InfluenceFunctionNamesZetaAndTheCall) {
  const pf::Influence f = pf::influenceFromName("sqrt(zeta - 0.5)", "in.xml: Discretization");
  EXPECT_EQ(pf::influenceValue(f, 0.75, 1.0), 0.5);
  try {
    pf::influenceValue(f, 0.25, 1.0);
    ADD_FAILURE() << "sqrt(-0.25) gave a value";
  } catch (const pf::InputError& err) {
    EXPECT_STREQ(err.what(),
                 "in.xml: Discretization: 'Influence Function' = 'sqrt(zeta - 0.5)' is nan at zeta = 0.25, horizon = 1: "
                 "sqrt(-0.25) is undefined");
  }
}

}  // namespace
