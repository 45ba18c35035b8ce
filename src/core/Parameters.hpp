#pragma once
// Declared parameters of a component (a material, a solver, an output list) and their validated values.
// A component lists its ParameterSpecs once; the input layer checks a deck against them (type, range,
// choices, required) and hands the component a ParameterValues, so no component re-checks its input.
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace pf {

struct ParameterSpec {
  enum class Kind { Double, Int, Bool, String, Scalar /* string or number (YAML turns "0" into a number) */ };
  std::string name;
  Kind kind = Kind::Double;
  bool required = false;
  std::string doc;
  std::string defaultValue;            // as text ("1e-5", "true", "One"); empty: none (documented only)
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false, maxExclusive = false;
  std::vector<std::string> choices;    // for String: the allowed values (empty: any)

  // Builders, e.g. ParameterSpec::real("Density", "mass density [kg/m^3]").need().positive().
  static ParameterSpec real(std::string name, std::string doc = "");
  static ParameterSpec integer(std::string name, std::string doc = "");
  static ParameterSpec flag(std::string name, std::string doc = "");
  static ParameterSpec text(std::string name, std::string doc = "");
  static ParameterSpec scalar(std::string name, std::string doc = "");
  ParameterSpec need() const;                          // required
  ParameterSpec byDefault(std::string value) const;    // default value (text form)
  ParameterSpec positive() const;                      // > 0
  ParameterSpec nonNegative() const;                   // >= 0
  ParameterSpec atLeast(double v) const;               // >= v
  ParameterSpec above(double v) const;                 // > v
  ParameterSpec below(double v) const;                 // < v
  ParameterSpec atMost(double v) const;                // <= v
  ParameterSpec oneOf(std::vector<std::string> values) const;

  bool hasRange() const { return min > -std::numeric_limits<double>::infinity() || max < std::numeric_limits<double>::infinity(); }
  std::string rangeText() const;  // "> 0", ">= 1", "in [0, 0.5)", "" if none
  // Empty if v is inside the range, else the reason ("must be positive (got -1)").
  std::string rangeError(double v) const;
};

const char* kindName(ParameterSpec::Kind k);

struct ParameterValues;

// What the input layer does for a deck's list, for values that come from elsewhere (the material-point
// driver, tests): rejects unknown names, missing required ones, values outside a range or not among the
// choices (InputError naming in.where() and the parameter), and fills in.defaults. Types are the caller's.
void applySpecs(const std::vector<ParameterSpec>& specs, ParameterValues& in);

// Validated values of one parameter list, converted to plain types (bools as 0/1, ints as doubles).
// has() is true only for what the deck gave; get() falls back to the spec's default.
struct ParameterValues {
  std::string name;       // the list name, e.g. "My Steel" (a material) or "Verlet"
  std::string inputFile;  // for error messages
  std::string path;       // parameter path of the list in the deck, e.g. "Materials/My Steel"
  std::map<std::string, double> values;
  std::map<std::string, std::string> strings;
  std::map<std::string, std::string> defaults;  // spec defaults (text) for parameters not given

  bool has(const std::string& key) const { return values.count(key) != 0 || strings.count(key) != 0; }
  double get(const std::string& key) const;                   // given or default; InputError if neither
  double get(const std::string& key, double fallback) const;  // given, else fallback
  bool flag(const std::string& key) const { return get(key) != 0.0; }
  std::string text(const std::string& key) const;             // given or default; InputError if neither
  std::string where() const { return inputFile + ": " + path; }
};

}  // namespace pf
