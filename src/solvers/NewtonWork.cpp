#include "NewtonWork.hpp"

#include <cstdio>

namespace pf {

std::string NewtonWork::summary() const {
  const double total = seconds > 0 ? seconds : 1.0;
  auto part = [&](double s) {
    char b[48];
    std::snprintf(b, sizeof b, "%.2f s, %.0f %%", s, 100.0 * s / total);
    return std::string(b);
  };
  const double rest = krylovSeconds - tangentSeconds - preconditionerSeconds;
  char line[768];
  std::snprintf(line, sizeof line,
                "NOX work: %ld Newton iterations, %ld GMRES iterations; %ld residuals (%s), %ld linearisations (%s, "
                "%.0f MB kept), %ld tangent products (%s), %ld preconditioner applications (%s), %ld preconditioner builds (%s), GMRES's own work (%s); "
                "%.2f s in the engine on rank 0",
                newtonIterations, krylovIterations, residuals, part(residualSeconds).c_str(), linearisations,
                part(linearisationSeconds).c_str(), tangentBytes / 1e6, tangentProducts,
                part(tangentSeconds).c_str(), preconditionerApplications, part(preconditionerSeconds).c_str(),
                preconditionerBuilds, part(buildSeconds).c_str(), part(rest > 0 ? rest : 0.0).c_str(), seconds);
  return line;
}

}  // namespace pf
