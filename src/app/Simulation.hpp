#pragma once
// One run of `periforge input.xml`: read and validate the deck, build the model, run the solver, write
// output. Returns the process exit code; user mistakes become one-line errors, not crashes.
#include <string>

namespace pf {

int runSimulation(const std::string& inputFile);

}  // namespace pf
