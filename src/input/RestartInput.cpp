// The "Restart" list -> RestartSpec: where and how often checkpoints are written.
#include "Sections.hpp"

namespace pf {

std::vector<ParameterSpec> restartSpecs() {
  using S = ParameterSpec;
  return {S::text("Checkpoint Filename", "the checkpoint file, rewritten in place (atomically) at every checkpoint; "
                                         "default: `<Output Filename>.restart` of the first output list"),
          S::integer("Checkpoint Frequency", "write a checkpoint after every step whose number (the CSV's `step` "
                                             "column: load steps, or Verlet time steps, counted over all solvers) "
                                             "is a multiple of n")
              .need()
              .atLeast(1)};
}

RestartSpec parseRestart(const PL& r, const std::string& file, const std::vector<OutputSpec>& outputs) {
  const ParameterValues v = readList(r, restartSpecs(), {}, file, "Restart");
  RestartSpec s;
  s.given = true;
  s.frequency = static_cast<int>(v.get("Checkpoint Frequency"));
  if (v.has("Checkpoint Filename")) {
    s.checkpointFile = v.text("Checkpoint Filename");
    if (s.checkpointFile.empty()) fail(file, "Restart", "'Checkpoint Filename' is empty");
  } else if (outputs.empty()) {
    fail(file, "Restart", "'Checkpoint Filename' is needed when the deck has no Output list");
  } else {
    s.checkpointFile = outputs.front().filename + ".restart";
  }
  return s;
}

}  // namespace pf
