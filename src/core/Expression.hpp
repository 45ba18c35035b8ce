#pragma once
// Boundary-condition values as run-time expressions in x, y, z (reference coordinates) and t, compiled
// by Trilinos' Pamgen RTCompiler like Peridigm: "0.0", "-0.1*t/0.00005" or a full body assigning
// "value" (if/else if/else blocks allowed). Compile errors are InputErrors naming the context.
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
  // False if x, y and z never appear: callers may then evaluate once per time for all nodes.
  bool dependsOnSpace() const { return dependsOnSpace_; }
  const std::string& text() const { return text_; }
  const std::string& context() const { return context_; }

 private:
  std::string text_, context_;
  bool dependsOnSpace_ = false;
  std::unique_ptr<PG_RuntimeCompiler::Function> fn_;
  mutable std::mutex mutex_;
};

}  // namespace pf
