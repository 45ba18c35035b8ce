#include "StrictXml.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <set>

#include "ListReader.hpp"

namespace pf {

namespace {

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

void checkValue(const std::string& type, const std::string& raw, const std::string& file, const std::string& path,
                const std::string& name) {
  const std::string text = trimmed(raw);
  const std::string what = "'" + name + "' = '" + raw + "'";
  char* end = nullptr;
  errno = 0;
  if (type == "double") {
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') fail(file, path, what + " is not a number");
    if (!std::isfinite(v) || errno == ERANGE) fail(file, path, what + " is not a finite number");
  } else if (type == "int") {
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0') fail(file, path, what + " is not an integer");
    if (errno == ERANGE || v < INT_MIN || v > INT_MAX) fail(file, path, what + " is out of the int range");
  }
}

void walk(const Teuchos::XMLObject& list, const std::string& file, const std::string& path) {
  std::set<std::string> names;
  for (int i = 0; i < list.numChildren(); ++i) {
    const Teuchos::XMLObject& c = list.getChild(i);
    if (c.getTag() != "Parameter" && c.getTag() != "ParameterList") continue;
    if (!c.hasAttribute("name")) continue;  // Teuchos reports it
    const std::string name = c.getAttribute("name");
    if (!names.insert(name).second)
      fail(file, path, "'" + name + "' is given twice (a deck names each parameter or sub-list once)");
    if (c.getTag() == "ParameterList") {
      walk(c, file, path == "top level" ? name : path + "/" + name);
    } else if (c.hasAttribute("type") && c.hasAttribute("value")) {
      checkValue(c.getAttribute("type"), c.getAttribute("value"), file, path, name);
    }
  }
}

}  // namespace

void checkStrictly(const Teuchos::XMLObject& deck, const std::string& file) { walk(deck, file, "top level"); }

}  // namespace pf
