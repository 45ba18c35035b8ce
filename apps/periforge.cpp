// periforge input.xml|input.yaml — runs one peridynamic simulation (see README.md and docs/input.md).
// periforge input.xml --restart checkpoint — continues the deck's run from a checkpoint of its Restart list.
// periforge --estimate input.xml [--np N] — prints points, bonds and bytes per rank, allocates nothing.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "app/Simulation.hpp"
#include "app/SizeGuard.hpp"
#include "parallel/Communicator.hpp"

namespace {

const char* kUsage =
    "usage: periforge input.xml|input.yaml [--restart checkpoint]\n       periforge --estimate input.xml [--np N]\n";

// --estimate: np is the run's rank count unless --np N names another; rank 0 alone answers.
int estimate(int argc, char** argv, int rank, int size) {
  int np = size;
  if (argc == 5 && std::strcmp(argv[3], "--np") == 0) {
    char* end = nullptr;
    const long n = std::strtol(argv[4], &end, 10);
    if (*end != '\0' || n < 1 || n > 1000000) {
      if (rank == 0) std::fprintf(stderr, "periforge: --np wants a positive integer, got '%s'\n", argv[4]);
      return 2;
    }
    np = static_cast<int>(n);
  } else if (argc != 3) {
    if (rank == 0) std::fputs(kUsage, stderr);
    return 2;
  }
  return rank == 0 ? pf::runEstimate(argv[2], np) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);  // MPI_Finalize when main returns
  const int rank = mpi.rank();
  if (argc >= 2 && std::strcmp(argv[1], "--estimate") == 0)
    return estimate(argc, argv, rank, pf::Communicator::world().size());
  int code = 0;
  const bool restart = argc == 4 && std::strcmp(argv[2], "--restart") == 0;
  if ((argc != 2 && !restart) || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    if (rank == 0) std::fputs(kUsage, argc == 2 ? stdout : stderr);
    code = argc == 2 ? 0 : 2;
  } else {
    code = pf::runSimulation(argv[1], restart ? argv[3] : "");
  }
  return code;
}
