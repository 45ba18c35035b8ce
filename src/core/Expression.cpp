#include "Expression.hpp"

#include <cctype>

#include <RTC_FunctionRTC.hh>

#include "InputError.hpp"
#include "RtcFunctions.hpp"
#include "Words.hpp"

namespace pf {

namespace {

std::vector<std::string> identifiers(const std::string& s) {
  std::vector<std::string> ids;
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char c = s[i];
    if (std::isalpha(c) || c == '_') {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      ids.push_back(s.substr(i, j - i));
      i = j;
    } else if (std::isdigit(c) || c == '.') {
      // Skip a number whole so the exponent in "1e-3" is not read as an identifier.
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.')) {
        if ((s[j] == 'e' || s[j] == 'E') && j + 1 < s.size() && (s[j + 1] == '-' || s[j + 1] == '+')) ++j;
        ++j;
      }
      i = j;
    } else {
      ++i;
    }
  }
  return ids;
}

// Peridigm decks give a bare right-hand side ("0.0"); full bodies assign "value" themselves.
bool assignsValue(const std::string& s) {
  for (std::size_t pos = s.find("value"); pos != std::string::npos; pos = s.find("value", pos + 1)) {
    if (pos > 0 && (std::isalnum(static_cast<unsigned char>(s[pos - 1])) || s[pos - 1] == '_')) continue;
    std::size_t j = pos + 5;
    if (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) continue;
    while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    if (j < s.size() && s[j] == '=' && (j + 1 >= s.size() || s[j + 1] != '=')) return true;
  }
  return false;
}

}  // namespace

Expression::Expression(const std::string& text, const std::string& context) : text_(text), context_(context) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(context + ": expression is empty");
  for (const std::string& id : identifiers(text)) {
    if (id == "x" || id == "y" || id == "z") dependsOnSpace_ = true;
    const std::string refused = refusedRtcFunction(id);
    if (!refused.empty()) throw InputError(context + ": expression '" + oneLine(text) + "': " + refused);
  }
  std::string body = text;
  if (!assignsValue(body)) {
    body = "value = " + body;
  }
  const std::size_t last = body.find_last_not_of(" \t\r\n");
  if (body[last] != ';' && body[last] != '}') body += ";";
  installCheckedRtcFunctions();
  fn_ = std::make_unique<PG_RuntimeCompiler::Function>(5, "pf_expression");
  for (const char* v : {"x", "y", "z", "t", "value"}) fn_->addVar("double", v);
  bool compiled = false;
  const std::string escape = compileRtcBody(*fn_, text, body, compiled);
  if (!escape.empty() || !compiled)
    throw InputError(context + ": cannot compile expression '" + oneLine(text) + "': " +
                     (escape.empty() ? oneLine(fn_->getErrors()) : escape));
  // The compiler folds constant calls: sqrt(-1) written as such fails here, once, for every point.
  const std::string folded = takeRtcDomainError();
  if (!folded.empty()) throw InputError(context + ": expression '" + oneLine(text) + "': " + folded);
  // A trial run catches run-time errors (e.g. an unknown function) at input time, not mid-solve. Its
  // value does not matter: (0, 0, 0, 0) need not lie in the body or the run, so NaN there is no error.
  (*this)(0.0, 0.0, 0.0, 0.0);
}

Expression::~Expression() = default;

double Expression::operator()(double x, double y, double z, double t) const { return evaluate(x, y, z, t, nullptr); }

std::string Expression::whyNotFinite(double x, double y, double z, double t) const {
  std::string why;
  evaluate(x, y, z, t, &why);
  return why;
}

double Expression::evaluate(double x, double y, double z, double t, std::string* why) const {
  std::lock_guard<std::mutex> lock(mutex_);
  takeRtcDomainError();  // a stale reason from another expression on this thread is not ours
  fn_->varValueFill(0, x);
  fn_->varValueFill(1, y);
  fn_->varValueFill(2, z);
  fn_->varValueFill(3, t);
  fn_->varValueFill(4, 0.0);
  if (!fn_->execute())
    throw InputError(context_ + ": cannot evaluate expression '" + oneLine(text_) + "': " +
                     oneLine(fn_->getErrors()));
  const std::string domain = takeRtcDomainError();
  if (why) *why = domain;
  return fn_->getValueOfVar("value");
}

}  // namespace pf
