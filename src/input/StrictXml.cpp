#include "StrictXml.hpp"

#include <cerrno>
#include <climits>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

#include "ListReader.hpp"
#include "core/Log.hpp"
#include "core/Words.hpp"

namespace pf {

namespace {

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

void checkText(const std::string& text, const std::string& what, const std::string& file, const std::string& path) {
  const std::string shown = printable(text);
  if (shown != text) fail(file, path, what + " '" + shown + "' holds bytes that are not text (shown as \\xNN)");
}

// The types Periforge reads (ListReader: double, int, bool, string; YAML's long long). Teuchos would
// convert others (float, Array(double), ...) or fail with a message naming no parameter; none is a
// parameter of any Periforge list.
const std::set<std::string> kTypes = {"double", "int", "long long", "bool", "string"};

void checkValue(const std::string& type, const std::string& raw, const std::string& file, const std::string& path,
                const std::string& name) {
  checkText(raw, "'" + name + "' =", file, path);
  if (kTypes.count(type) == 0)
    fail(file, path, "'" + name + "' has type '" + printable(type) + "'; Periforge reads 'double', 'int', 'bool' "
                     "and 'string'");
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
  } else if (type == "bool") {
    // Exactly what Teuchos accepts (case-insensitive, no blanks), named here instead of in its own words.
    std::string upper;
    for (char c : raw) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper != "TRUE" && upper != "FALSE" && upper != "YES" && upper != "NO" && upper != "1" && upper != "0")
      fail(file, path, what + " is not a bool (true, false, yes, no, 1 or 0)");
  }
}

void walk(const Teuchos::XMLObject& list, const std::string& file, const std::string& path) {
  std::set<std::string> names, warned;
  for (int i = 0; i < list.numChildren(); ++i) {
    const Teuchos::XMLObject& c = list.getChild(i);
    if (c.getTag() != "Parameter" && c.getTag() != "ParameterList") continue;
    if (!c.hasAttribute("name")) continue;  // Teuchos reports it
    const std::string name = c.getAttribute("name");
    checkText(name, c.getTag() == "Parameter" ? "parameter name" : "sub-list name", file, path);
    // A parameter given twice: Teuchos keeps the last value, and Peridigm's decks rely on it (two of its
    // regression decks repeat one), so it is read that way, with a warning. A sub-list given twice would be
    // merged entry by entry, which no deck means: still an error.
    if (!names.insert(name).second) {
      if (c.getTag() == "ParameterList")
        fail(file, path, "sub-list '" + name + "' is given twice (a deck names each sub-list once)");
      if (warned.insert(name).second)
        warn(file + ": " + path + ": '" + name + "' is given twice; the last value is used (as Teuchos reads it)");
    }
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
