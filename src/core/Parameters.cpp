#include "Parameters.hpp"

#include <cstdlib>
#include <sstream>

#include "InputError.hpp"

namespace pf {

namespace {

// The shortest text that reads back as v: a bound's message must not print 1.0000001 as "1".
std::string num(double v) {
  for (int digits = 6;; ++digits) {
    std::ostringstream s;
    s.precision(digits);
    s << v;
    if (digits >= 17 || std::strtod(s.str().c_str(), nullptr) == v) return s.str();
  }
}

ParameterSpec make(std::string name, ParameterSpec::Kind kind, std::string doc) {
  ParameterSpec s;
  s.name = std::move(name);
  s.kind = kind;
  s.doc = std::move(doc);
  return s;
}

}  // namespace

ParameterSpec ParameterSpec::real(std::string n, std::string d) { return make(std::move(n), Kind::Double, std::move(d)); }
ParameterSpec ParameterSpec::integer(std::string n, std::string d) { return make(std::move(n), Kind::Int, std::move(d)); }
ParameterSpec ParameterSpec::flag(std::string n, std::string d) { return make(std::move(n), Kind::Bool, std::move(d)); }
ParameterSpec ParameterSpec::text(std::string n, std::string d) { return make(std::move(n), Kind::String, std::move(d)); }
ParameterSpec ParameterSpec::scalar(std::string n, std::string d) { return make(std::move(n), Kind::Scalar, std::move(d)); }

ParameterSpec ParameterSpec::need() const { ParameterSpec s = *this; s.required = true; return s; }
ParameterSpec ParameterSpec::byDefault(std::string v) const { ParameterSpec s = *this; s.defaultValue = std::move(v); return s; }
ParameterSpec ParameterSpec::positive() const { ParameterSpec s = *this; s.min = 0; s.minExclusive = true; return s; }
ParameterSpec ParameterSpec::nonNegative() const { ParameterSpec s = *this; s.min = 0; s.minExclusive = false; return s; }
ParameterSpec ParameterSpec::atLeast(double v) const { ParameterSpec s = *this; s.min = v; s.minExclusive = false; return s; }
ParameterSpec ParameterSpec::above(double v) const { ParameterSpec s = *this; s.min = v; s.minExclusive = true; return s; }
ParameterSpec ParameterSpec::below(double v) const { ParameterSpec s = *this; s.max = v; s.maxExclusive = true; return s; }
ParameterSpec ParameterSpec::atMost(double v) const { ParameterSpec s = *this; s.max = v; s.maxExclusive = false; return s; }
ParameterSpec ParameterSpec::oneOf(std::vector<std::string> v) const { ParameterSpec s = *this; s.choices = std::move(v); return s; }

std::string ParameterSpec::rangeText() const {
  const bool lo = min > -std::numeric_limits<double>::infinity(), hi = max < std::numeric_limits<double>::infinity();
  if (lo && hi) return std::string("in ") + (minExclusive ? "(" : "[") + num(min) + ", " + num(max) + (maxExclusive ? ")" : "]");
  if (lo) return (minExclusive ? "> " : ">= ") + num(min);
  if (hi) return (maxExclusive ? "< " : "<= ") + num(max);
  return "";
}

std::string ParameterSpec::rangeError(double v) const {
  const bool ok = (minExclusive ? v > min : v >= min) && (maxExclusive ? v < max : v <= max);
  if (ok) return "";
  if (min == 0 && minExclusive && max == std::numeric_limits<double>::infinity())
    return "must be positive (got " + num(v) + ")";
  if (min == 1 && !minExclusive && max == std::numeric_limits<double>::infinity())
    return "must be at least 1 (got " + num(v) + ")";
  return "must be " + rangeText() + " (got " + num(v) + ")";
}

const char* kindName(ParameterSpec::Kind k) {
  switch (k) {
    case ParameterSpec::Kind::Double: return "double";
    case ParameterSpec::Kind::Int: return "int";
    case ParameterSpec::Kind::Bool: return "bool";
    case ParameterSpec::Kind::String: return "string";
    case ParameterSpec::Kind::Scalar: return "string or number";
  }
  return "?";
}

void applySpecs(const std::vector<ParameterSpec>& specs, ParameterValues& in) {
  auto fail = [&](const std::string& msg) { throw InputError(in.where() + ": " + msg); };
  auto declared = [&](const std::string& key) {
    for (const ParameterSpec& s : specs)
      if (s.name == key) return true;
    return key == "Material Model";  // every material list names its model
  };
  for (const auto& v : in.values)
    if (!declared(v.first)) fail("unknown parameter '" + v.first + "'");
  for (const auto& v : in.strings)
    if (!declared(v.first)) fail("unknown parameter '" + v.first + "'");
  for (const ParameterSpec& s : specs) {
    if (!in.has(s.name)) {
      if (s.required) fail("missing required parameter '" + s.name + "'");
      if (!s.defaultValue.empty()) in.defaults[s.name] = s.defaultValue;
      continue;
    }
    auto v = in.values.find(s.name);
    if (v != in.values.end() && s.kind != ParameterSpec::Kind::Bool) {
      const std::string why = s.rangeError(v->second);
      if (!why.empty()) fail("'" + s.name + "' " + why);
    }
    auto t = in.strings.find(s.name);
    if (!s.choices.empty() && t != in.strings.end()) {
      std::string names;
      for (const std::string& c : s.choices) names += (names.empty() ? "'" : ", '") + c + "'";
      bool ok = false;
      for (const std::string& c : s.choices) ok = ok || c == t->second;
      if (!ok) fail("'" + s.name + "' = '" + t->second + "' is not one of " + names);
    }
  }
}

double ParameterValues::get(const std::string& key) const {
  auto it = values.find(key);
  if (it != values.end()) return it->second;
  auto d = defaults.find(key);
  if (d != defaults.end()) {
    if (d->second == "true") return 1.0;
    if (d->second == "false") return 0.0;
    return std::strtod(d->second.c_str(), nullptr);
  }
  throw InputError(inputFile + ": " + path + ": missing required parameter '" + key + "'");
}

double ParameterValues::get(const std::string& key, double fallback) const {
  auto it = values.find(key);
  return it == values.end() ? fallback : it->second;
}

std::string ParameterValues::text(const std::string& key) const {
  auto it = strings.find(key);
  if (it != strings.end()) return it->second;
  auto d = defaults.find(key);
  if (d != defaults.end()) return d->second;
  throw InputError(inputFile + ": " + path + ": missing required parameter '" + key + "'");
}

}  // namespace pf
