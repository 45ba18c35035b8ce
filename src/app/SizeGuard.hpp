#pragma once
// The memory and size guard and `periforge --estimate`: both read the deck's SizeEstimate (no cloud built).
// guardSize throws InputError (the same on every rank) when the run would not fit; runEstimate prints the
// estimate for np ranks and returns the exit code.
#include <string>

#include "input/Deck.hpp"
#include "parallel/Communicator.hpp"

namespace pf {

// Limit: the deck's "Maximum Memory" if given, else the smallest MemAvailable of the ranks' machines.
void guardSize(const Deck& deck, const Communicator& comm);

// `periforge --estimate deck [--np N]`: points, bonds and bytes per rank at np (default: the run's ranks).
int runEstimate(const std::string& inputFile, int np);

}  // namespace pf
