#pragma once
// Boundary-condition values as run-time expressions in x, y, z (reference coordinates) and t, compiled
// by Trilinos' Pamgen RTCompiler like Peridigm: "0.0", "-0.1*t/0.00005" or a full body assigning
// "value" (if/else if/else blocks allowed). Compile errors are InputErrors naming the context. An argument
// outside a function's domain (sqrt(-1)) gives NaN, never an abort: whyNotFinite() says what failed.
#include <memory>
#include <mutex>
#include <string>

namespace PG_RuntimeCompiler {
class Function;
}

namespace pf {

class Expression {
 public:
  // context: where the text came from, for errors, e.g. "input.xml: Boundary Conditions/Left/Value".
  Expression(const std::string& text, const std::string& context);
  ~Expression();
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

  // Serialised by a mutex: the compiled function keeps its variables as state.
  double operator()(double x, double y, double z, double t) const;
  // Why the value at (x, y, z, t) is NaN, e.g. "sqrt(-0.4) is undefined"; "" when no function argument
  // was out of its domain there (the value may still be inf or NaN by arithmetic, e.g. 1/0).
  std::string whyNotFinite(double x, double y, double z, double t) const;
  // False if x, y and z never appear: callers may then evaluate once per time for all nodes.
  bool dependsOnSpace() const { return dependsOnSpace_; }
  const std::string& text() const { return text_; }
  const std::string& context() const { return context_; }

 private:
  double evaluate(double x, double y, double z, double t, std::string* why) const;

  std::string text_, context_;
  bool dependsOnSpace_ = false;
  std::unique_ptr<PG_RuntimeCompiler::Function> fn_;
  mutable std::mutex mutex_;
};

}  // namespace pf
