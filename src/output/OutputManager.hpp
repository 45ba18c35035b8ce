#pragma once
// Observes converged steps and writes what the Output list asks for: one merged Exodus II file every Output
// Frequency steps (rank 0 writes it a chunk of points at a time as the ranks send them, never holding a whole
// field: parallel/ChunkedGather.hpp), and a CSV history with reactions and probes every output step.
// Reaction_<Set>_<C> is the force the supports apply to the body on that node set: -sum (f + b) V;
// "Reaction Names" replaces <Set> by a short name per entry of "Reactions". Then Reaction_<Wall>_<C> per
// Rigid Wall: its force on the body in the reported step (sum m dv / dt, model/RigidWall.hpp). "Applied Displacement" names
// a Prescribed Displacement condition whose (space-independent) value at the step's time becomes the
// column Applied_Displacement, right after time and step.
//
// One manager per output list ("Output", or Peridigm's "Output1", "Output2", ...). Like Peridigm's, it counts
// every step reported to it over all solvers run in sequence (each solver reports its initial state too):
// call n (1-based) is written if Initial Output Step <= n <= Final Output Step + 1 and (n - 1) is a multiple
// of Output Frequency. The CSV's step column is n - 1. Global variables (Global_Kinetic_Energy) go to the
// Exodus globals; a list that asks for globals only gets Peridigm's one-dummy-node file.
//
// Files are written as <name>.e.part / <name>.csv.part under <name>.lock and get their final names in
// finish(); abandon() leaves them with a <name>.status line instead (OutputFiles). Rank 0 writes; every
// call that can fail there is agreed on collectively, so a failed write throws on every rank.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "model/ModelBuilder.hpp"
#include "output/ComputeClasses.hpp"
#include "output/ExodusWriter.hpp"
#include "solvers/Solver.hpp"

namespace pf {

class ChunkedGather;
struct CheckpointData;
class HistoryWriter;
class OutputFiles;

class OutputManager : public StepObserver {
 public:
  // out: one of the deck's output lists ("Output", "Output1", ...); deck names the file in messages.
  OutputManager(const OutputSpec& out, const Deck& deck, Problem& problem);
  ~OutputManager() override;
  void onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
              const std::vector<double>& f) override;
  // Collective: the run ended well; the parts become <name>.e / <name>.csv.
  // Whether the last onStep wrote a step to the Exodus file (its companions, the interface file, write with it).
  bool wroteExodusStep() const { return wroteExodus_; }
  void finish();
  // The run failed or was stopped (verb: "failed", "interrupted"): <name>.status says so, the parts stay.
  // Not collective (every rank may call it; rank 0 writes).
  void abandon(const std::string& verb, const std::string& line) noexcept;
  // A checkpoint: this list's step count and (rank 0) copies of its files as they stand, which are complete
  // up to the last reported step (rows are flushed and Exodus steps synced as they are written).
  void saveTo(CheckpointData& data) const;
  // A restart, before the first step is reported (collective): the part files become the checkpoint's
  // copies and continue from its step count, so the finished files equal an uninterrupted run's.
  void resumeFrom(const CheckpointData& data);
  std::string exodusFile() const { return exodusName_; }
  std::string historyFile() const { return historyName_; }

 private:
  struct Probe {
    std::string name;
    int local = -1;                       // owned-local index on the owning rank, else -1
    std::vector<std::string> variables;
  };
  struct Reaction {
    std::string set;
    std::string label;       // column label: the set's name or its "Reaction Names" entry
    std::vector<int> nodes;  // owned-local
  };
  void requireComputed(const std::string& var, const std::string& where) const;
  void requireGlobal(const std::string& var, const std::string& where) const;
  Probe locateProbe(const ProbeSpec& p, const std::string& listName) const;
  int nearestPoint(const double* at, double* d2, double* where) const;
  double spacingAt(int q, const double* xq) const;
  bool dummyNodeFile() const;  // Peridigm's file for global data only: one dummy node
  void gatherBlockIds();
  void writeCoordinates();
  void addReactions(const OutputSpec& out);
  void addCompute(const ComputeSpec& spec);
  void addTensor(const std::string& tensor, const std::string& where);
  std::string storedComponent(const std::string& var) const;
  void findElementVariablesOfBlocks();
  void onRoot(const std::function<void()>& write, bool everyRank = false);
  void openFiles();
  void openWriters(bool append);
  std::vector<std::string> historyColumns() const;
  std::string firstNonFinite(int begin, int count, const std::vector<const double*>& values) const;
  std::string stepText() const;
  SolverFailure nonFinite(const std::string& var, const char* kind, double value) const;
  std::vector<double> historyRow(const StepReport& report, const std::vector<double>& u,
                                 const std::vector<double>& v, const std::vector<double>& f);
  void writeExodusStep(double time, const std::vector<double>& u, const std::vector<double>& v,
                       const std::vector<double>& f);
  // Component k (3 per owned node) of a force term's output (Model::termOutput), 0 when the model has no such term.
  double termValue(const std::string& name, int k) const;
  double nodeValue(const std::string& var, int comp, int i, const std::vector<double>& u, const std::vector<double>& v,
                   const std::vector<double>& f) const;

  Problem& pb_;
  Model& model_;
  std::string inputFile_;
  int frequency_ = 1;
  long first_ = 1, last_ = 0;  // Initial / Final Output Step (last_ = 0: no limit)
  long count_ = 0;             // steps reported so far, over all solvers
  long nonlinearIterations_ = 0;  // Nonlinear_Solver_Iterations: StepReport::nonlinearIterations summed over them
  bool exodus_ = false;
  bool wroteExodus_ = false;
  std::string exodusName_, historyName_, baseName_, where_;
  long lastStep_ = -1;     // the CSV step of the last reported step (-1: none yet), and its time
  double lastTime_ = 0.0;
  std::vector<std::string> nodalVectors_, elementScalars_, globals_;
  std::vector<std::string> nodalScalars_;  // the model's fields (Temperature, ...): nodal, as Peridigm writes them
  std::vector<Probe> probes_;
  std::vector<Reaction> reactions_;
  // The element variables of a whole tensor the model computes (Model::kinematicTensors), each with its array (F_ or
  // Kinv_, 9 per owned node) and component; the arrays are filled at each step written, only when some are asked for.
  std::map<std::string, std::pair<const std::vector<double>*, int>> kinematic_;
  std::vector<double> F_, Kinv_;
  std::map<int, std::vector<char>> elementVariablesOf_;  // per block id: which elementScalars_ it has
  ComputeClasses computes_;             // Peridigm's compute classes this list writes (globals)
  std::vector<double> computeValues_;   // their values at the step being written (historyRow)
  std::unique_ptr<ExodusWriter> writer_;
  std::unique_ptr<ChunkedGather> gather_;  // built once: which owned points go to rank 0 in which chunk
  BlockRuns blockRuns_;  // rank 0, while the Exodus writer is made: the points' blocks in cloud order
  std::unique_ptr<HistoryWriter> history_;
  std::unique_ptr<OutputFiles> files_;  // rank 0
  std::vector<double> bodyForce_;
  std::shared_ptr<const Expression> applied_;  // "Applied Displacement" condition's value, or null
};

}  // namespace pf
