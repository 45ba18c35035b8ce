#include "SizeGuard.hpp"

#include <cstdio>

#include "core/InputError.hpp"
#include "discretization/SizeEstimate.hpp"

namespace pf {

void guardSize(const Deck& deck, const Communicator& comm) {
  const SizeEstimate e = estimateSize(deck);
  // Every rank must reach the same verdict: the smallest MemAvailable decides (ranks read it at
  // different moments, and may sit on different machines).
  const double available = -comm.max(-availableMemory());
  if (deck.maxMemory > 0.0)
    checkSize(deck, e, comm.size(), deck.maxMemory, "'Maximum Memory'");
  else
    checkSize(deck, e, comm.size(), available, "the memory available (MemAvailable)");
}

int runEstimate(const std::string& inputFile, int np) {
  try {
    const Deck deck = readDeck(inputFile);
    const SizeEstimate e = estimateSize(deck);
    const char* bound = e.holes ? " (holes not subtracted: an upper bound)" : e.meshFile ? " (mesh file)" : "";
    std::printf("periforge: %s: estimate at np %d%s\n", inputFile.c_str(), np, bound);
    std::printf("  points           %.0f (%.4g per rank)\n", e.points, e.points / np);
    std::printf("  bonds            %.0f (%.4g per rank, %.0f per interior point%s)\n", e.bonds, e.bonds / np,
                e.family, e.meshFile ? ", from the mean spacing" : "");
    std::printf("  bytes per rank   %s\n", bytesText(bytesPerRank(e, np)).c_str());
    const bool given = deck.maxMemory > 0.0;
    const double limit = given ? deck.maxMemory : availableMemory();
    const std::string limitName = given ? "'Maximum Memory'" : "the memory available (MemAvailable)";
    std::printf("  bytes per run    %s (limit: %s %s)\n", bytesText(bytesPerRun(e, np)).c_str(), limitName.c_str(),
                bytesText(limit).c_str());
    try {  // the verdict a run would reach, reported rather than acted on
      checkSize(deck, e, np, limit, limitName);
      std::printf("  verdict          fits\n");
    } catch (const InputError& refused) {
      std::printf("  verdict          a run would be refused: %s\n", refused.what());
    }
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "periforge: input error: %s\n", e.what());
    return 1;
  }
}

}  // namespace pf
