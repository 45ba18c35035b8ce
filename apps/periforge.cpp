// periforge input.xml|input.yaml — runs one peridynamic simulation (see README.md and docs/input.md).
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "app/Simulation.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  int code = 0;
  if (argc != 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    if (rank == 0) std::fprintf(argc == 2 ? stdout : stderr, "usage: periforge input.xml|input.yaml\n");
    code = argc == 2 ? 0 : 2;
  } else {
    code = pf::runSimulation(argv[1]);
  }
  MPI_Finalize();
  return code;
}
