#pragma once
// Peridigm's Data Loader (docs/input.md, "Data Loader"): a nodal scalar field read from an Exodus results file and
// imposed on every point at every evaluated time t, linearly interpolated between the file's two output times
// around t (Peridigm_DataLoader.cpp). The file's node k is the point of cloud index k (Peridigm's output order).
#include <string>
#include <utility>
#include <vector>

#include "input/Deck.hpp"
#include "input/ExodusFile.hpp"
#include "model/FieldSource.hpp"
#include "model/Model.hpp"

namespace pf {

class LoadedField : public FieldSource {
 public:
  // path: the data file; variable: its nodal variable; ownedGids: each owned point's cloud index; numPoints: every
  // rank's; pointIds: the id each point's node must carry, in cloud order (Peridigm checks the file's node ids
  // against its points' ids), empty (or not one per point): 1..numPoints. InputError (deck, Data Loader parameter, file) for a file whose
  // nodes do not match the points, or without at least two rising output times.
  LoadedField(const std::string& path, const std::string& variable, const std::string& inputFile,
              const std::vector<int>& ownedGids, long long numPoints, const std::vector<long long>& pointIds);
  // t must lie within the file's times (a round-off's overshoot, 1e-12 of their span, reads the end value);
  // otherwise InputError.
  void valuesAt(double t, double* values) override;

 private:
  ExodusFile file_;  // open for the run: each new pair of times reads two steps of the owned nodes
  int variable_ = 0;
  std::vector<double> times_;
  std::vector<std::pair<int, int>> order_;  // (cloud index, owned index), ascending cloud index
  int step_ = -1;                           // the loaded pair: steps step_, step_ + 1 (0-based); -1: none
  std::vector<double> first_, second_;      // their values per owned point
  void readStep(int step, std::vector<double>& out) const;
};

// The deck's Data Loader as a field of the model with a LoadedField source (no-op without the list). Collective.
void addLoadedField(const Deck& deck, Model& model, const std::string& inputFile);

}  // namespace pf
