#include "LoadedField.hpp"

#include <algorithm>
#include <memory>
#include <sstream>

#include "core/InputError.hpp"
#include "input/ExodusNodalData.hpp"

namespace pf {

namespace {
// Nodes read per ex_get_partial_var call: bounds the buffer at 8 MB whatever the mesh size.
constexpr long long kChunk = 1 << 20;

std::string text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

LoadedField::LoadedField(const std::string& path, const std::string& variable, const std::string& inputFile,
                         const std::vector<int>& ownedGids, long long numPoints, const std::vector<long long>& pointIds)
    : file_(path, inputFile, "Data Loader/File Name", "data file") {
  variable_ = exodusNodalVariableIndex(file_, variable);
  times_ = exodusTimes(file_);
  if (times_.size() < 2) file_.fail("it has fewer than two output times");
  const long long nodes = file_.summary().nodes;
  if (nodes != numPoints)
    file_.fail("it has " + std::to_string(nodes) + " nodes, the discretization " + std::to_string(numPoints) +
               " points (one node per point, in the points' order)");
  const std::vector<long long> ids = exodusIdMap(file_, true);
  for (long long k = 0; k < nodes; ++k) {
    const long long want = pointIds.size() != static_cast<std::size_t>(numPoints) ? k + 1 : pointIds[static_cast<std::size_t>(k)];
    if (ids[static_cast<std::size_t>(k)] != want)
      file_.fail("its node " + std::to_string(k + 1) + " has id " + std::to_string(ids[static_cast<std::size_t>(k)]) +
                 ", the point it stands for " + std::to_string(want) + " (the file's nodes must be the points, in order)");
  }
  for (std::size_t i = 0; i < ownedGids.size(); ++i) order_.emplace_back(ownedGids[i], static_cast<int>(i));
  std::sort(order_.begin(), order_.end());
  first_.assign(ownedGids.size(), 0.0);
  second_.assign(ownedGids.size(), 0.0);
}

void LoadedField::readStep(int step, std::vector<double>& out) const {
  std::vector<double> chunk;
  const long long nodes = file_.summary().nodes;
  for (std::size_t w = 0; w < order_.size();) {
    const long long start = order_[w].first, count = std::min(kChunk, nodes - start);
    chunk.resize(static_cast<std::size_t>(count));
    readNodalValues(file_, step + 1, variable_, start + 1, count, chunk.data());
    for (; w < order_.size() && order_[w].first < start + count; ++w)
      out[static_cast<std::size_t>(order_[w].second)] = chunk[static_cast<std::size_t>(order_[w].first - start)];
  }
}

void LoadedField::valuesAt(double t, double* values) {
  const double span = times_.back() - times_.front(), slack = 1e-12 * span;
  if (t < times_.front() - slack || t > times_.back() + slack)
    file_.fail("time " + text(t) + " lies outside its output times [" + text(times_.front()) + ", " +
               text(times_.back()) + "]");
  t = std::min(std::max(t, times_.front()), times_.back());
  // Peridigm's rule: keep the loaded pair while t lies within it, else load the first pair of the file around t.
  if (step_ < 0 || t < times_[step_] || t > times_[step_ + 1]) {
    std::size_t k = 0;
    while (k + 2 < times_.size() && !(t >= times_[k] && t <= times_[k + 1])) ++k;
    step_ = static_cast<int>(k);
    readStep(step_, first_);
    readStep(step_ + 1, second_);
  }
  const double c = (t - times_[step_]) / (times_[step_ + 1] - times_[step_]);
  for (std::size_t i = 0; i < first_.size(); ++i) values[i] = (1.0 - c) * first_[i] + c * second_[i];
}

void addLoadedField(const Deck& deck, Model& model, const std::string& inputFile) {
  if (!deck.dataLoader.given) return;
  std::vector<long long> ids;  // an Exodus mesh's points carry its element ids (Peridigm's point ids), others 1..N
  if (deck.discretization.type == DiscretizationSpec::Type::Exodus) {
    const ExodusFile mesh(deck.discretization.meshFile, inputFile);
    ids = exodusIdMap(mesh, false);
  }
  const DistributedLayout& layout = model.layout();
  const std::vector<int> owned(layout.gids().begin(), layout.gids().begin() + layout.numOwned());
  auto source = std::make_shared<LoadedField>(deck.dataLoader.file, deck.dataLoader.field, inputFile, owned,
                                              layout.numGlobal(), ids);
  model.addField(deck.dataLoader.field);
  model.fields().setSource(deck.dataLoader.field, std::move(source));
}

}  // namespace pf
