// periforge input.xml|input.yaml — runs one peridynamic simulation (see README.md and docs/input.md).
#include <cstdio>
#include <cstring>
#include <string>

#include "app/Simulation.hpp"
#include "parallel/Communicator.hpp"

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);  // MPI_Finalize when main returns
  const int rank = mpi.rank();
  int code = 0;
  if (argc != 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    if (rank == 0) std::fprintf(argc == 2 ? stdout : stderr, "usage: periforge input.xml|input.yaml\n");
    code = argc == 2 ? 0 : 2;
  } else {
    code = pf::runSimulation(argv[1]);
  }
  return code;
}
