#include "RtcFunctions.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>

#include <RTC_RegistrarRTC.hh>

namespace pf {

namespace {

thread_local std::string domainError;

using PG_RuntimeCompiler::RTBoundFunc;
using PG_RuntimeCompiler::Value;

// One argument, checked against [lo, hi] before the library function is applied.
class CheckedUnary : public RTBoundFunc {
 public:
  CheckedUnary(const char* name, double (*f)(double), double lo, double hi)
      : RTBoundFunc(name, 1), f_(f), lo_(lo), hi_(hi) {}
  double execute(Value** args) override {
    const double a = args[0]->getValue();
    if (a >= lo_ && a <= hi_) return f_(a);
    if (domainError.empty()) {
      // Six digits, or as many more as it takes to show the argument outside the domain
      // (acos(-1.0000001) must not read "acos(-1)").
      char arg[40];
      for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(arg, sizeof arg, "%.*g", digits, a);
        const double shown = std::strtod(arg, nullptr);
        if (!(shown >= lo_ && shown <= hi_)) break;
      }
      domainError = _name + "(" + arg + ") is undefined";
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

 private:
  double (*f_)(double);
  double lo_, hi_;
};

double sqrtOf(double a) { return std::sqrt(a); }
double logOf(double a) { return std::log(a); }
double log10Of(double a) { return std::log10(a); }
double asinOf(double a) { return std::asin(a); }
double acosOf(double a) { return std::acos(a); }

}  // namespace

void installCheckedRtcFunctions() {
  static std::once_flag once;
  std::call_once(once, [] {
    using PG_RuntimeCompiler::Registrar;
    // The standard set first: the registrar fills it lazily and would then overwrite ours.
    Registrar::setupStandardFunctions();
    const double inf = std::numeric_limits<double>::infinity();
    // log(0) = -inf is left to the caller's finiteness check, as is any other non-finite result.
    static CheckedUnary sqrtF("sqrt", sqrtOf, 0.0, inf), logF("log", logOf, 0.0, inf),
        log10F("log10", log10Of, 0.0, inf), asinF("asin", asinOf, -1.0, 1.0), acosF("acos", acosOf, -1.0, 1.0);
    for (RTBoundFunc* f : {static_cast<RTBoundFunc*>(&sqrtF), static_cast<RTBoundFunc*>(&logF),
                           static_cast<RTBoundFunc*>(&log10F), static_cast<RTBoundFunc*>(&asinF),
                           static_cast<RTBoundFunc*>(&acosF)})
      Registrar::registerFunction(f);
  });
}

std::string takeRtcDomainError() {
  std::string e;
  e.swap(domainError);
  return e;
}

std::string refusedRtcFunction(const std::string& name) {
  if (name == "printf" || name == "scanf" || name == "readline" || name == "tester")
    return "'" + name + "' is not available in expressions (it reads or writes text)";
  if (name == "rand" || name == "drand")
    return "'" + name + "' is not available in expressions (it would differ between ranks and between runs)";
  return "";
}

}  // namespace pf
