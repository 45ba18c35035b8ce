#pragma once
// Pamgen's RTCompiler asserts (SIGABRT, exit 134) when sqrt, log or log10 get a negative argument or asin,
// acos one outside [-1, 1]. installCheckedRtcFunctions() registers replacements under the same names that
// return NaN and record why instead; callers turn the NaN into an error naming the expression and the
// point. Both are thread-safe; the recorded reason is per thread.
#include <string>

namespace PG_RuntimeCompiler {
class Function;
}

namespace pf {

// Idempotent; call before compiling any RTCompiler function.
void installCheckedRtcFunctions();

// The first domain error recorded on this thread since the last call ("" if none), e.g. "sqrt(-0.4)";
// clears it.
std::string takeRtcDomainError();

// The first number in an expression that the RTCompiler cannot read, with why ("'1.0.0' is not a number",
// "the number '1e400' is out of range"), or "" when none. Its tokenizer takes digits, '.', e/E and a sign
// after the exponent as one number and asserts (SIGABRT) on one that is neither an int nor a double, or lets
// std::stod/std::stoi throw for one beyond their range. Quoted text and comments hold no numbers.
std::string malformedRtcNumber(const std::string& text);

// Runs fn.addBody(body) for the expression text unless text holds a malformed number (see above), and
// catches an exception escaping the compiler. Returns what kept it from compiling safely ("" when addBody
// ran; its own verdict is then in compiled, its errors in fn.getErrors()).
std::string compileRtcBody(PG_RuntimeCompiler::Function& fn, const std::string& text, const std::string& body,
                           bool& compiled);

// Functions the RTCompiler offers that no Periforge expression may call, with the reason, or "" if name
// is allowed: printf, scanf, readline and tester abort on arguments of the wrong kind; rand and drand
// would give every rank and every run other values.
std::string refusedRtcFunction(const std::string& name);

}  // namespace pf
