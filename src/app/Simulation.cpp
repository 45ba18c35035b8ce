#include "Simulation.hpp"

#include <chrono>
#include <cstdio>
#include <set>

#include "discretization/Discretization.hpp"
#include "input/Input.hpp"
#include "core/InputError.hpp"
#include "input/InputSchema.hpp"
#include "core/Material.hpp"
#include "model/ModelBuilder.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Communicator.hpp"
#include "core/Log.hpp"
#include "solvers/SolverFactory.hpp"

namespace pf {
namespace {

// Hands each reported step to every output list's manager (Output, or Output1, Output2, ...).
class OutputFanout : public StepObserver {
 public:
  std::vector<std::unique_ptr<OutputManager>> managers;
  void onStep(const StepReport& r, const std::vector<double>& u, const std::vector<double>& v,
              const std::vector<double>& f) override {
    for (auto& m : managers) m->onStep(r, u, v, f);
  }
};

// Every rank reaches the same verdict on input errors (all ranks read the same deck), so each rank
// can stop on its own; rank 0 alone prints.
int fail(int rank, const std::string& kind, const std::string& what) {
  if (rank == 0) std::fprintf(stderr, "periforge: %s%s\n", kind.c_str(), what.c_str());
  return 1;
}

// Peridigm's block group "Block Names" = "default" takes every block of the discretization that no other
// group names: rewritten here into those block_<n> names (none: the group is dropped), so that the model
// builder sees explicit names only. Costs one extra discretization, only for decks that use it.
void expandDefaultBlock(Teuchos::ParameterList& input, const std::string& inputFile) {
  Teuchos::ParameterList& blocks = input.sublist("Blocks");
  std::string group;
  std::set<int> named;
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    if (!blocks.entry(it).isList()) continue;
    for (const std::string& n : splitWords(getText(blocks.sublist(blocks.name(it)), "Block Names", "")))
      if (n == "default")
        group = blocks.name(it);
      else
        named.insert(std::stoi(n.substr(6)));  // block_<n>, validated
  }
  if (group.empty()) return;
  const auto slash = inputFile.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : inputFile.substr(0, slash);
  const PointCloud cloud = buildDiscretization(input.sublist("Discretization"), inputFile, dir, maxBlockHorizon(input));
  std::set<int> rest(cloud.block.begin(), cloud.block.end());
  std::string names;
  for (int b : rest)
    if (!named.count(b)) names += (names.empty() ? "" : " ") + std::string("block_") + std::to_string(b);
  if (names.empty())
    blocks.remove(group);
  else
    blocks.sublist(group).set("Block Names", names);
}

}  // namespace

int runSimulation(const std::string& inputFile) {
  const Communicator comm = Communicator::world();
  const int rank = comm.rank();
  setPrintingRank(rank == 0);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  try {
    Teuchos::RCP<Teuchos::ParameterList> input = readInput(inputFile);
    validateInput(*input, inputFile);
    expandDefaultBlock(*input, inputFile);
    // "Solver", or Peridigm's Solver1, Solver2, ... run in sequence, each continuing from the state
    // (displacement, velocity, material history) the previous one ended with.
    const std::vector<std::string> solverLists = numberedLists(*input, "Solver");
    std::vector<std::unique_ptr<Solver>> solvers;
    for (const std::string& n : solverLists) solvers.push_back(makeSolver(input->sublist(n), inputFile, n));
    Problem problem = buildProblem(*input, inputFile, comm);
    Model& model = *problem.model;
    const double setup = std::chrono::duration<double>(Clock::now() - start).count();
    const double bonds = model.sum(static_cast<double>(model.layout().family().numBonds()));
    if (rank == 0)
      std::printf("periforge: %s: %d points, %.0f bonds, %d rank(s), set-up %.2f s, solver %s\n", inputFile.c_str(),
                  model.layout().numGlobal(), bonds, comm.size(), setup, solvers.front()->name().c_str());

    OutputFanout output;
    for (const std::string& n : numberedLists(*input, "Output"))
      output.managers.push_back(std::make_unique<OutputManager>(*input, n, inputFile, problem));
    const double t0 = solverTimes(input->sublist(solverLists.front())).front();
    std::vector<double> u(model.numDofs(), 0.0), v(model.numDofs(), 0.0);
    for (const NodalLoad& l : problem.initialDisplacements) {
      const std::vector<double>& x = model.coordinates();
      for (int i : l.nodes) u[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
    }
    for (const NodalLoad& l : problem.initialVelocities) {
      const std::vector<double>& x = model.coordinates();
      for (int i : l.nodes) v[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
    }
    for (std::size_t k = 0; k < solvers.size(); ++k) {
      const Teuchos::ParameterList& s = input->sublist(solverLists[k]);
      if (rank == 0 && solvers.size() > 1)
        std::printf("periforge: %s: solver %s\n", solverLists[k].c_str(), solvers[k]->name().c_str());
      solvers[k]->run(model, u, v, solverTimes(s), output);
    }
    if (rank == 0) {
      std::string files;
      for (const auto& m : output.managers) {
        files += (files.empty() ? "" : ", ") + m->historyFile();
        if (!m->exodusFile().empty()) files += " and " + m->exodusFile();
      }
      std::printf("periforge: done in %.2f s; wrote %s\n", std::chrono::duration<double>(Clock::now() - start).count(),
                  files.empty() ? "nothing (no Output list)" : files.c_str());
    }
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
