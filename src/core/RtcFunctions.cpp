#include "RtcFunctions.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <mutex>

#include <RTC_FunctionRTC.hh>
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

std::string malformedRtcNumber(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\'') {
      const std::size_t close = s.find(static_cast<char>(c), i + 1);
      i = close == std::string::npos ? s.size() : close + 1;
    } else if (s.compare(i, 2, "/*") == 0 || s.compare(i, 2, "//") == 0) {
      const std::size_t close = s[i + 1] == '*' ? s.find("*/", i + 2) : s.find('\n', i);
      i = close == std::string::npos ? s.size() : close + 2;
    } else if (std::isalpha(c) || c == '_') {
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
    } else if (std::isdigit(c) || c == '.') {
      std::size_t j = i, dots = 0, exps = 0, digits = 0;  // digits: of the mantissa
      bool dotAfterExp = false;
      for (; j < s.size(); ++j) {
        const char d = s[j];
        if (std::isdigit(static_cast<unsigned char>(d))) digits += exps == 0 ? 1 : 0;
        else if (d == '.') dots++, dotAfterExp = dotAfterExp || exps > 0;
        else if (d == 'e' || d == 'E') ++exps;
        else if (!((d == '+' || d == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))) break;
      }
      const std::string number = s.substr(i, j - i);
      i = j;
      if (dots > 1 || exps > 1 || dotAfterExp || digits == 0) return "'" + number + "' is not a number";
      errno = 0;
      const bool isInt = dots == 0 && exps == 0;
      const double v = isInt ? static_cast<double>(std::strtoll(number.c_str(), nullptr, 10))
                             : std::strtod(number.c_str(), nullptr);
      if (errno == ERANGE || (isInt && v > 2147483647.0)) return "the number '" + number + "' is out of range";
    } else {
      ++i;
    }
  }
  return "";
}

std::string compileRtcBody(PG_RuntimeCompiler::Function& fn, const std::string& text, const std::string& body,
                           bool& compiled) {
  compiled = false;
  const std::string bad = malformedRtcNumber(text);
  if (!bad.empty()) return bad;
  try {
    compiled = fn.addBody(body);
  } catch (const std::exception& e) {  // a safety net: malformedRtcNumber names the escapes known so far
    return e.what();
  }
  return "";
}

std::string refusedRtcFunction(const std::string& name) {
  if (name == "printf" || name == "scanf" || name == "readline" || name == "tester")
    return "'" + name + "' is not available in expressions (it reads or writes text)";
  if (name == "rand" || name == "drand")
    return "'" + name + "' is not available in expressions (it would differ between ranks and between runs)";
  return "";
}

}  // namespace pf
