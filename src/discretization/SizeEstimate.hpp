#pragma once
// How big a run will be, from the validated Deck alone (no cloud built): points, bonds and bytes, so that
// a run too large for the machine (or for 32-bit ids) stops with one line before allocating anything.
// Counts are doubles (they may exceed every integer type); bonds and bytes are upper bounds (docs/input.md).
#include <array>
#include <string>

#include "input/Deck.hpp"

namespace pf {

struct SizeEstimate {
  double points = 0.0;      // exact for grids without holes; holes are not subtracted (an upper bound)
  double family = 0.0;      // bonds of an interior point (lattice points of the horizon ball)
  double bonds = 0.0;       // points * family: an upper bound (points near a surface have fewer)
  double loadTimes = 0.0;   // solver times every rank holds (SolverSpec::times)
  bool holes = false;       // the deck has holes: points (and bonds) are upper bounds
  bool meshFile = false;    // Text File: the spacing is inferred from the mesh, the family approximate
  bool newtonKrylov = false;  // a NOX solver: its pair-stiffness preconditioner and Krylov basis cost more
  bool damage = false;        // a block with a damage model: per-bond broken flags (and QS break-round copies)
};

// Peak resident bytes of one rank = fixed + perRankPoint * points + (perPoint * points + perBond * bonds) / np:
// a per-rank term fitted when every rank held the whole cloud (kept as an upper bound), and each rank's share
// of the distributed state. Fitted to peak RSS of real runs
// (docs/input.md, "Size and memory guard").
struct MemoryModel {
  double fixed;         // executable, Trilinos, MPI: resident before the deck matters
  double perRankPoint;  // fitted to the replicated PointCloud of before the distributed set-up: an upper bound
  double perPoint;      // distributed per-point state, maps, vectors, output buffers
  double perBond;       // neighbour, length, influence, bond state (and NOX's pair matrix)
};
MemoryModel memoryModel(const SizeEstimate& e);  // Verlet and ADR, or NOX

// Throws InputError naming the deck when a count is unusable (a mesh file that cannot be read).
SizeEstimate estimateSize(const Deck& deck);

// Lattice points other than the centre whose distance from it is at most radius (partialVolume: whose cell
// reaches into the ball), on a grid with the given cell edges (0: flat axis) and at most extent[a] points
// along each axis. Exact up to a few thousand cells of radius, then the continuum volume.
double latticeFamily(const std::array<double, 3>& cell, const std::array<double, 3>& extent, double radius,
                     bool partialVolume);

// Bytes one rank holds at np ranks, and the whole run (np ranks on one machine share its memory).
double bytesPerRank(const SizeEstimate& e, int np);
double bytesPerRun(const SizeEstimate& e, int np);

// MemAvailable of /proc/meminfo in bytes, or 0 when it cannot be read (then only Maximum Memory limits).
double availableMemory();

// Refuses (InputError, one line naming the deck, the estimate, the limit and what to change) a run whose ids
// overflow 32 bits or whose bytesPerRun exceeds limit (limitName says where the limit came from).
void checkSize(const Deck& deck, const SizeEstimate& e, int np, double limit, const std::string& limitName);

// "12.3 GB", "840 MB": decimal units, three digits.
std::string bytesText(double bytes);

}  // namespace pf
