#pragma once
// Pamgen's RTCompiler asserts (SIGABRT, exit 134) when sqrt, log or log10 get a negative argument or asin,
// acos one outside [-1, 1]. installCheckedRtcFunctions() registers replacements under the same names that
// return NaN and record why instead; callers turn the NaN into an error naming the expression and the
// point. Both are thread-safe; the recorded reason is per thread.
#include <string>

namespace pf {

// Idempotent; call before compiling any RTCompiler function.
void installCheckedRtcFunctions();

// The first domain error recorded on this thread since the last call ("" if none), e.g. "sqrt(-0.4)";
// clears it.
std::string takeRtcDomainError();

// Functions the RTCompiler offers that no Periforge expression may call, with the reason, or "" if name
// is allowed: printf, scanf, readline and tester abort on arguments of the wrong kind; rand and drand
// would give every rank and every run other values.
std::string refusedRtcFunction(const std::string& name);

}  // namespace pf
