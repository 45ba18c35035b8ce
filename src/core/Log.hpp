#pragma once
// Warnings for the user, printed once per run although every rank reaches them: only the printing rank
// prints. The app marks it (rank 0) at start-up; until then every process prints, as a serial tool or a
// unit test should. Kept here, below MPI, so that any layer can warn without asking MPI for its rank.
#include <string>

namespace pf {

void setPrintingRank(bool printing);
bool isPrintingRank();
// "periforge: warning: <what>" on stderr, on the printing rank only.
void warn(const std::string& what);

}  // namespace pf
