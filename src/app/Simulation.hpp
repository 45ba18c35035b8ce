#pragma once
// One run of `periforge input.xml`: read and validate the deck, build the model, run the solver, write
// output. Returns the process exit code; user mistakes become one-line errors, not crashes. restartFile
// (or empty): continue from that checkpoint of the same deck (written by its Restart list, at any rank count).
#include <string>

namespace pf {

int runSimulation(const std::string& inputFile, const std::string& restartFile = "");

}  // namespace pf
