#include "Log.hpp"

#include <cstdio>

namespace pf {
namespace {
bool printing = true;  // set once at start-up, before any thread; read only afterwards
}  // namespace

void setPrintingRank(bool p) { printing = p; }

bool isPrintingRank() { return printing; }

void warn(const std::string& what) {
  if (printing) std::fprintf(stderr, "periforge: warning: %s\n", what.c_str());
}

}  // namespace pf
