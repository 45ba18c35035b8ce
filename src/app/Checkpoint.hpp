#pragma once
// Restart from a checkpoint (docs/output.md, "Restart"). A Checkpointer observes every reported step after
// the output lists and, every Checkpoint Frequency steps, writes what a run needs to continue into one file
// (output/CheckpointFile): the deck's fingerprint, u and v per point, every history field's committed values
// per point or per bond (in global orders, so that any rank count reads it), the solver's position and
// carry, and every output list's step count and files so far. Rank 0 writes and reads the file; the fields
// pass through it chunk by chunk (parallel/ChunkedGather), so no rank holds a whole field. loadCheckpoint
// opens one and checks it against this run's deck; applyCheckpoint puts the state in place and says where
// to go on (src/app/CheckpointRestore.cpp).
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "input/Deck.hpp"
#include "model/ModelBuilder.hpp"
#include "output/CheckpointFile.hpp"
#include "output/OutputManager.hpp"
#include "parallel/ChunkedGather.hpp"
#include "parallel/GlobalBondOrder.hpp"
#include "solvers/Solver.hpp"

namespace pf {

// What identifies a deck's run for a checkpoint: points, bonds, coordinates, materials, history fields,
// solvers and output lists, as (item, text) pairs that are the same at any rank count. Collective.
std::vector<std::pair<std::string, std::string>> runFingerprint(const Deck& deck, const Problem& problem);

class Checkpointer : public StepObserver {
 public:
  // managers: the run's output lists, whose files each checkpoint copies. count: steps already reported
  // (a restart's), so the step numbers go on as an uninterrupted run's.
  Checkpointer(const Deck& deck, Problem& problem, const std::vector<std::unique_ptr<OutputManager>>& managers,
               long count);
  void setSolver(std::size_t index) { solver_ = index; }  // the solver list the next reports come from
  void onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
              const std::vector<double>& f) override;  // collective

 private:
  void write(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v);
  const Deck& deck_;
  Problem& problem_;
  const std::vector<std::unique_ptr<OutputManager>>& managers_;
  GlobalBondOrder bonds_;
  ChunkedGather points_;  // owned points to rank 0 in cloud order, chunk by chunk
  ChunkedGather bondPoints_;  // the same for per-bond values, in smaller chunks (GlobalBondOrder::chunkPoints)
  std::vector<std::pair<std::string, std::string>> fingerprint_;  // computed once (a collective sum)
  long count_;
  std::size_t solver_ = 0;
};

// Where a restarted run goes on: solver list `solver` after its step resume.step; `count` steps were
// reported before (over all solver lists).
struct RestartPoint {
  std::size_t solver = 0;
  long count = 0;
  SolverResume resume;
};

// Collective: rank 0 opens file (data.source) and every rank gets its small sections and its numbers
// sections' sizes, checked against this run; InputError "'file': why" on every rank for a missing,
// truncated, corrupt or foreign checkpoint.
CheckpointData loadCheckpoint(const std::string& file, const Deck& deck, const Problem& problem);
// Collective: u, v and the committed state of every history field from data; the point to continue from.
RestartPoint applyCheckpoint(const std::string& file, const CheckpointData& data, Problem& problem,
                             std::vector<double>& u, std::vector<double>& v);

}  // namespace pf
