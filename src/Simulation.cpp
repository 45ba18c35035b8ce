#include "Simulation.hpp"

#include <Epetra_MpiComm.h>
#include <mpi.h>

#include <chrono>
#include <cstdio>

#include "Input.hpp"
#include "InputError.hpp"
#include "InputSchema.hpp"
#include "Material.hpp"
#include "ModelBuilder.hpp"
#include "OutputManager.hpp"
#include "SolverFactory.hpp"

namespace pf {
namespace {

// Every rank reaches the same verdict on input errors (all ranks read the same deck), so each rank
// can stop on its own; rank 0 alone prints.
int fail(int rank, const std::string& kind, const std::string& what) {
  if (rank == 0) std::fprintf(stderr, "periforge: %s%s\n", kind.c_str(), what.c_str());
  return 1;
}

}  // namespace

int runSimulation(const std::string& inputFile) {
  Epetra_MpiComm comm(MPI_COMM_WORLD);
  const int rank = comm.MyPID();
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  try {
    Teuchos::RCP<Teuchos::ParameterList> input = readInput(inputFile);
    validateInput(*input, inputFile);
    std::unique_ptr<Solver> solver = makeSolver(input->sublist("Solver"), inputFile);
    Problem problem = buildProblem(*input, inputFile, comm);
    Model& model = *problem.model;
    const double setup = std::chrono::duration<double>(Clock::now() - start).count();
    const double bonds = model.sum(static_cast<double>(model.layout().family().numBonds()));
    if (rank == 0)
      std::printf("periforge: %s: %d points, %.0f bonds, %d rank(s), set-up %.2f s, solver %s\n", inputFile.c_str(),
                  model.layout().numGlobal(), bonds, comm.NumProc(), setup, solver->name().c_str());

    OutputManager output(*input, inputFile, problem);
    const Teuchos::ParameterList& s = input->sublist("Solver");
    const double t0 = getNumber(s, "Initial Time", 0.0), t1 = getNumber(s, "Final Time");
    if (!(t1 > t0)) throw InputError(inputFile + ": Solver: 'Final Time' must be greater than 'Initial Time'");
    std::vector<double> u(model.numDofs(), 0.0), v(model.numDofs(), 0.0);
    for (const NodalLoad& l : problem.initialDisplacements) {
      const std::vector<double>& x = model.coordinates();
      for (int i : l.nodes) u[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
    }
    for (const NodalLoad& l : problem.initialVelocities) {
      const std::vector<double>& x = model.coordinates();
      for (int i : l.nodes) v[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
    }
    solver->run(model, u, v, t0, t1, output);
    if (rank == 0)
      std::printf("periforge: done in %.2f s; wrote %s%s%s\n",
                  std::chrono::duration<double>(Clock::now() - start).count(), output.historyFile().c_str(),
                  output.exodusFile().empty() ? "" : " and ", output.exodusFile().c_str());
    return 0;
  } catch (const InputError& e) {
    return fail(rank, "input error: ", e.what());
  } catch (const SolverFailure& e) {
    return fail(rank, "solver failed: ", std::string(e.what()) + " (output holds the converged steps only)");
  } catch (const ConstitutiveFailure& e) {
    return fail(rank, "material update failed: ", e.what());
  } catch (const std::exception& e) {
    return fail(rank, "error: ", e.what());
  }
}

}  // namespace pf
