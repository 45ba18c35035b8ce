#include "Simulation.hpp"

#include <chrono>
#include <cstdio>

#include "Checkpoint.hpp"
#include "OutputFanout.hpp"
#include "core/StopSignal.hpp"
#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "core/Material.hpp"
#include "core/SolverEntry.hpp"
#include "input/Deck.hpp"
#include "model/ModelBuilder.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Communicator.hpp"
#include "solvers/SolverFactory.hpp"
#include "SizeGuard.hpp"

namespace pf {
namespace {

using Clock = std::chrono::steady_clock;

// How a run ended badly: the one line rank 0 prints (after "periforge: "), the exit code, and the verb
// of the output files' status line.
struct Outcome {
  std::string line;
  int code = 1;
  std::string verb = "failed";
};

// deckFile: an input error raised after the deck was read (e.g. a material's, at the first force evaluation)
// does not know the file; the line names it as every input error does.
Outcome describe(const std::exception_ptr& error, const std::string& deckFile) {
  const std::string kept = " (the .part output files hold the converged steps)";
  try {
    std::rethrow_exception(error);
  } catch (const Interrupted& e) {
    return {e.what() + kept, 128 + e.signal(), "interrupted"};
  } catch (const InputError& e) {
    const std::string what = e.what();
    const bool named = what.compare(0, deckFile.size() + 1, deckFile + ":") == 0;
    return {"input error: " + (named || deckFile.empty() ? what : deckFile + ": " + what)};
  } catch (const SolverFailure& e) {
    return {std::string("solver failed: ") + e.what() + kept};
  } catch (const ConstitutiveFailure& e) {
    return {std::string("material update failed: ") + e.what()};
  } catch (const std::exception& e) {
    return {std::string("error: ") + e.what()};
  } catch (...) {
    return {"error: unknown exception"};
  }
}

// u, v from the initial conditions at t0. Every condition the solvers evaluate at t0 must be finite there:
// an inf or nan start would otherwise surface steps later as an unexplained non-finite state.
void initialState(const Problem& problem, double t0, std::vector<double>& u, std::vector<double>& v) {
  const Model& model = *problem.model;
  const std::vector<double>& x = model.coordinates();
  model.requireFiniteLoads(t0);
  for (const NodalLoad& l : problem.initialDisplacements) {
    requireFiniteLoad(model, l, t0);
    for (int i : l.nodes) u[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
  }
  for (const NodalLoad& l : problem.initialVelocities) {
    requireFiniteLoad(model, l, t0);
    for (int i : l.nodes) v[3 * i + l.coordinate] = (*l.value)(x[3 * i], x[3 * i + 1], x[3 * i + 2], t0);
  }
}

// Collective: u = v = 0 everywhere and nothing can move the body (RunStart::atRest): no condition, contact, wall or
// field (a temperature change would expand it).
bool atRest(const Model& model, const std::vector<double>& u, const std::vector<double>& v) {
  double moving = model.hasConditions() || model.hasForceTerms() || !model.rigidWalls().empty() || !model.fields().empty();
  for (std::size_t k = 0; k < u.size() && moving == 0.0; ++k) moving = u[k] != 0.0 || v[k] != 0.0;
  return model.max(moving) == 0.0;
}

// "Solver", or Peridigm's Solver1, Solver2, ... run in sequence, each continuing from the state
// (displacement, velocity, material history) the previous one ended with. A restart begins with the
// checkpoint's solver list, after its step.
void solve(const Deck& deck, const std::vector<std::unique_ptr<Solver>>& solvers, Problem& problem,
           std::vector<double>& u, std::vector<double>& v, OutputFanout& output, const RestartPoint* from,
           Checkpointer* checkpointer) {
  Model& model = *problem.model;
  for (std::size_t k = from ? from->solver : 0; k < solvers.size(); ++k) {
    if (model.layout().rank() == 0 && solvers.size() > 1)
      std::printf("periforge: %s: solver %s\n", deck.solvers[k].listName.c_str(), solvers[k]->name().c_str());
    if (from && k == from->solver) solvers[k]->resumeAfter(from->resume);
    if (checkpointer) checkpointer->setSolver(k);
    solvers[k]->run(model, u, v, deck.solvers[k].times, output);
  }
}

// Collective: the checkpoint's state in place of the initial one; where the run goes on.
RestartPoint restartFrom(const std::string& file, const Deck& deck, Problem& problem, std::vector<double>& u,
                         std::vector<double>& v, CheckpointData& data) {
  data = loadCheckpoint(file, deck, problem);
  const RestartPoint at = applyCheckpoint(file, data, problem, u, v);
  if (at.solver >= deck.solvers.size())  // the fingerprint has the solver lists: only a forged file gets here
    throw InputError("restart: '" + file + "': no solver list " + std::to_string(at.solver + 1) + " in this deck");
  if (problem.model->layout().rank() == 0)
    std::printf("periforge: restart from %s after step %ld (t = %g)\n", file.c_str(), at.count - 1, at.resume.time);
  return at;
}

void printDone(const OutputFanout& output, Clock::time_point start) {
  std::string files;
  for (const auto& m : output.managers) {
    files += (files.empty() ? "" : ", ") + m->historyFile();
    if (!m->exodusFile().empty()) files += " and " + m->exodusFile();
  }
  std::printf("periforge: done in %.2f s; wrote %s\n", std::chrono::duration<double>(Clock::now() - start).count(),
              files.empty() ? "nothing (no Output list)" : files.c_str());
}

// Collective. What each rank owns and receives per exchange (scripts/comm_model predicts the same from the
// partition's geometry): owned and ghost points per rank, and the ranks a rank receives ghosts from.
void reportPartition(const DistributedLayout& layout) {
  const double ghosts = layout.numGhosts();
  // One reduction for the maxima (a minimum is the maximum of the negated value), one for the total.
  const double owned = layout.numOwned();
  const double mine[5] = {owned, -owned, ghosts, -ghosts, static_cast<double>(layout.numGhostSources())};
  double all[5];
  layout.comm().max(mine, all, 5);
  const double ghostSum = layout.sum(ghosts);
  if (layout.rank() == 0)
    std::printf("partition: owned points per rank %.0f..%.0f, ghost points per rank %.0f..%.0f (total %.0f), "
                "ranks a rank receives from: at most %.0f\n",
                -all[1], all[0], -all[3], all[2], ghostSum, all[4]);
}

// Throws on failure, after marking every output list's files as failed or interrupted.
void run(const std::string& inputFile, const std::string& restartFile, const Communicator& comm,
         Clock::time_point start) {
  const Deck deck = readDeck(inputFile);
  guardSize(deck, comm);  // before anything sized by the deck is allocated
  std::vector<std::unique_ptr<Solver>> solvers;  // made first: a bad solver list fails before the set-up
  for (const SolverSpec& s : deck.solvers) solvers.push_back(makeSolver(s));
  Problem problem = buildProblem(deck, comm);
  Model& model = *problem.model;
  const double setup = std::chrono::duration<double>(Clock::now() - start).count();
  const double bonds = model.sum(static_cast<double>(model.layout().family().numBonds()));
  if (comm.rank() == 0)
    std::printf("periforge: %s: %d points, %.0f bonds, %d rank(s), set-up %.2f s, solver %s\n", inputFile.c_str(),
                model.layout().numGlobal(), bonds, comm.size(), setup, solvers.front()->name().c_str());
  if (comm.size() > 1) reportPartition(model.layout());
  // Checks that need the model come before any output file is opened.
  std::vector<double> u(model.numDofs(), 0.0), v(model.numDofs(), 0.0);
  initialState(problem, deck.solvers.front().times.front(), u, v);
  model.setPrescribedBaseline(deck.solvers.front().times.front(), u.data());  // before a restart replaces u
  CheckpointData restart;
  std::unique_ptr<RestartPoint> from;
  if (!restartFile.empty()) from = std::make_unique<RestartPoint>(restartFrom(restartFile, deck, problem, u, v, restart));
  for (std::size_t k = 0; k < solvers.size(); ++k) {
    if (solvers[k]->advances("Displacement") && !model.hasForceModel())
      throw InputError(inputFile + ": " + deck.solvers[k].listName + ": solver '" + deck.solvers[k].type +
                       "' advances the displacement, but no block has a force model (Diffusion blocks only conduct heat)");
    solvers[k]->check(model, RunStart{k == 0 && atRest(model, u, v), deck.solvers[k].times.front(),
                                      deck.solvers[k].times.back()});
  }
  OutputFanout output(comm);
  std::unique_ptr<Checkpointer> checkpointer;  // or null: no Restart list; the fanout calls it after each step
  std::unique_ptr<InterfaceOutput> interfaces;  // or null: no Construct Interfaces
  try {
    for (const OutputSpec& o : deck.outputs) output.managers.push_back(std::make_unique<OutputManager>(o, deck, problem));
    if (deck.discretization.constructInterfaces) interfaces = std::make_unique<InterfaceOutput>(deck, model, inputFile);
    output.interfaces = interfaces.get();
    if (from)
      for (const auto& m : output.managers) m->resumeFrom(restart);
    restart = CheckpointData();  // the copies of the output files are on disk again
    if (deck.restart.given)
      checkpointer = std::make_unique<Checkpointer>(deck, problem, output.managers, from ? from->count : 0);
    output.checkpointer = checkpointer.get();
    solve(deck, solvers, problem, u, v, output, from.get(), checkpointer.get());
    output.finish();
  } catch (...) {
    const Outcome o = describe(std::current_exception(), inputFile);
    output.abandon(o.verb, o.line);
    throw;
  }
  if (comm.rank() == 0) printDone(output, start);
}

}  // namespace

int runSimulation(const std::string& inputFile, const std::string& restartFile) {
  const Communicator comm = Communicator::world();
  setPrintingRank(comm.rank() == 0);
  installStopHandlers();
  try {
    run(inputFile, restartFile, comm, Clock::now());
    return 0;
  } catch (...) {
    // Every rank reaches the same verdict (input is read by all; rank-local failures are agreed on
    // collectively), so each rank stops on its own; rank 0 alone prints.
    const Outcome o = describe(std::current_exception(), inputFile);
    if (comm.rank() == 0) std::fprintf(stderr, "periforge: %s\n", o.line.c_str());
    return o.code;
  }
}

}  // namespace pf
