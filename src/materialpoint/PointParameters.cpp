#include "PointParameters.hpp"

#include <stdexcept>

#include "core/InputError.hpp"

namespace pf {

namespace {

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

void addParameter(const MaterialEntry& entry, const std::string& assignment, std::map<std::string, double>& values,
                  std::map<std::string, std::string>& strings) {
  const std::size_t eq = assignment.find('=');
  const std::string where = "periforge-point: --param '" + assignment + "'";
  if (eq == std::string::npos) throw InputError(where + ": expected Name=value");
  const std::string name = trim(assignment.substr(0, eq)), text = trim(assignment.substr(eq + 1));
  const ParameterSpec* spec = nullptr;
  std::string known;
  for (const ParameterSpec& s : entry.parameters) {
    if (s.name == name) spec = &s;
    known += (known.empty() ? "'" : ", '") + s.name + "'";
  }
  if (!spec) throw InputError(where + ": model '" + entry.model + "' has no parameter '" + name + "' (" + known + ")");
  switch (spec->kind) {
    case ParameterSpec::Kind::Bool:
      if (text != "true" && text != "false" && text != "1" && text != "0")
        throw InputError(where + ": '" + name + "' is a bool (true or false), got '" + text + "'");
      values[name] = (text == "true" || text == "1") ? 1.0 : 0.0;
      return;
    case ParameterSpec::Kind::String:
      strings[name] = text;
      return;
    default: {
      std::size_t used = 0;
      double v = 0.0;
      try { v = std::stod(text, &used); } catch (const std::exception&) { used = 0; }
      if (text.empty() || used != text.size()) {
        if (spec->kind == ParameterSpec::Kind::Scalar) { strings[name] = text; return; }
        throw InputError(where + ": '" + name + "' needs a number, got '" + text + "'");
      }
      if (spec->kind == ParameterSpec::Kind::Int && v != static_cast<double>(static_cast<long>(v)))
        throw InputError(where + ": '" + name + "' needs an integer, got '" + text + "'");
      values[name] = v;
    }
  }
}

}  // namespace pf
