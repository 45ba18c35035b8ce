#include "Simulation.hpp"

#include <chrono>
#include <cstdio>

#include "core/InputError.hpp"
#include "input/Deck.hpp"
#include "core/Material.hpp"
#include "model/ModelBuilder.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Communicator.hpp"
#include "core/Log.hpp"
#include "solvers/SolverFactory.hpp"
#include "SizeGuard.hpp"

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

}  // namespace

int runSimulation(const std::string& inputFile) {
  const Communicator comm = Communicator::world();
  const int rank = comm.rank();
  setPrintingRank(rank == 0);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  try {
    const Deck deck = readDeck(inputFile);
    guardSize(deck, comm);  // before anything sized by the deck is allocated
    // "Solver", or Peridigm's Solver1, Solver2, ... run in sequence, each continuing from the state
    // (displacement, velocity, material history) the previous one ended with.
    std::vector<std::unique_ptr<Solver>> solvers;
    for (const SolverSpec& s : deck.solvers) solvers.push_back(makeSolver(s));
    Problem problem = buildProblem(deck, comm);
    Model& model = *problem.model;
    const double setup = std::chrono::duration<double>(Clock::now() - start).count();
    const double bonds = model.sum(static_cast<double>(model.layout().family().numBonds()));
    if (rank == 0)
      std::printf("periforge: %s: %d points, %.0f bonds, %d rank(s), set-up %.2f s, solver %s\n", inputFile.c_str(),
                  model.layout().numGlobal(), bonds, comm.size(), setup, solvers.front()->name().c_str());

    OutputFanout output;
    for (const OutputSpec& o : deck.outputs) output.managers.push_back(std::make_unique<OutputManager>(o, deck, problem));
    const double t0 = deck.solvers.front().times.front();
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
      if (rank == 0 && solvers.size() > 1)
        std::printf("periforge: %s: solver %s\n", deck.solvers[k].listName.c_str(), solvers[k]->name().c_str());
      solvers[k]->run(model, u, v, deck.solvers[k].times, output);
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
