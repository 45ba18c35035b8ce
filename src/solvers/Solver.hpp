#pragma once
// A time or load-step integrator over a Model. Solvers know nothing of materials, files or output: they
// advance (u, v) from t0 to t1 and report each completed step to an observer, which decides what to
// write. A step is reported only after it has converged and its state is finite; otherwise the solver
// throws SolverFailure (on every rank), so nothing non-converged or non-finite is presented as a result.
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pf {

class Model;

class SolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A solver's own state after a reported step, beyond u, v and the model's committed state: what it needs
// to continue from there bit for bit. Named vectors (3 per owned node) and scalars; an observer may store
// them (a checkpoint) and hand them back through Solver::resumeAfter, but never interprets them.
struct SolverCarry {
  std::vector<std::pair<std::string, const std::vector<double>*>> vectors;
  std::vector<std::pair<std::string, double>> scalars;
};

// Where a solver continues: after its reported step `step` at `time`, with the carry it reported there.
struct SolverResume {
  long step = 0;
  double time = 0.0;
  std::map<std::string, std::vector<double>> vectors;
  std::map<std::string, double> scalars;
  // The named entry; std::logic_error if absent (the checkpoint layer stores every one a report carried).
  const std::vector<double>& vector(const std::string& name) const;
  double scalar(const std::string& name) const;
};

struct StepReport {
  int step = 0;          // 0 = initial state
  double time = 0.0;
  int iterations = 0;    // solver iterations of this step (0 for explicit steps)
  double residual = 0.0; // final residual norm of the step (the solver's measure: force, or Implicit's
                         // Peridigm residual), 0 for explicit steps
  double tolerance = 0.0;
  double wallSeconds = 0.0;  // wall time of this step
  const SolverCarry* carry = nullptr;  // what resuming after this step needs (see SolverCarry)
  // The step's share of Peridigm's Nonlinear_Solver_Iterations: the passes of its nonlinear solver (NOX's step()
  // calls, a Newton loop's iterations); 0 for explicit and dynamic-relaxation steps, which Peridigm does not count.
  int nonlinearIterations = 0;
  // Peridigm's adaptive load stepping sets its output lists' cadence from the solver (QuasiStatic's `Adaptive
  // Load-Stepping`): > 0 replaces each Output list's `Output Frequency` for this step (its `Switch to Verlet` list's
  // Output Frequency); the factor multiplies it (`Adaptive output frequency`, doubled with each step reduction).
  int outputEvery = 0;
  int outputEveryFactor = 1;
};

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // u, v: displacement and velocity; f: internal force density; all 3 per owned node.
  virtual void onStep(const StepReport& report, const std::vector<double>& u, const std::vector<double>& v,
                      const std::vector<double>& f) = 0;
};

// What a run starts from, for a check that depends on it. atRest: u = v = 0 at every point and nothing can set the
// body in motion (no prescribed displacement, body force, pressure, contact, wall or field): it stays at rest up to
// the round-off of its forces there. startTime, endTime: the solver's first and last load time.
struct RunStart {
  bool atRest = false;
  double startTime = 0.0, endTime = 0.0;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;
  // Checks the options against the built model before any output file is opened: InputError for a
  // setting the model cannot run (every rank reaches the same verdict), warnings for doubtful ones.
  virtual void check(const Model&) const {}
  // The same knowing what the run starts from (Simulation's call; a solver started mid-run gets the one above).
  virtual void check(const Model& model, const RunStart&) const { check(model); }
  // u, v hold the initial state on entry (prescribed values are applied by the solver); on return they
  // hold the final state, from which a following solver (Peridigm's Solver2 after Solver1) continues.
  // times: the start time, then the end of every load step (quasi-static solvers step through them all;
  // Verlet runs from times.front() to times.back() with its own time step). At least two, increasing.
  virtual void run(Model& model, std::vector<double>& u, std::vector<double>& v, const std::vector<double>& times,
                   StepObserver& observer) = 0;
  // The next run() continues after resume.step instead of starting at times.front(): u, v and the model's
  // committed state are those of that step (a restart), nothing up to it is reported again.
  // The fields this run advances (the deck's `Solve For` flags, SolverSpec::fields); set before run().
  void setFields(std::vector<std::string> fields) { fields_ = std::move(fields); }
  bool advances(const std::string& field) const {
    for (const std::string& f : fields_)
      if (f == field) return true;
    return false;
  }
  void resumeAfter(SolverResume resume) {
    resume_ = std::move(resume);
    resuming_ = true;
  }

 protected:
  // run() calls this once: the resume point, or null for a run from the start.
  const SolverResume* takeResume() {
    if (!resuming_) return nullptr;
    resuming_ = false;
    return &resume_;
  }

 private:
  SolverResume resume_;
  bool resuming_ = false;
  std::vector<std::string> fields_;
};

}  // namespace pf
