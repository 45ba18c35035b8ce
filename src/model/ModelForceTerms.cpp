// Model's force terms besides the materials (core/ForceTerm.hpp): their sum for the solvers, each one's output.
#include <algorithm>

#include "Model.hpp"

namespace pf {

void Model::addForceTerm(std::unique_ptr<ForceTerm> term) {
  termOutputs_[term->outputName()].assign(numDofs(), 0.0);
  forceTerms_.push_back(std::move(term));
}

void Model::termForce(long step, double t, const double* y, const double* v, double* f) {
  std::fill(f, f + numDofs(), 0.0);
  for (const std::unique_ptr<ForceTerm>& term : forceTerms_) {
    std::vector<double>& out = termOutputs_[term->outputName()];
    term->force(step, t, y, v, out.data());
    for (int k = 0; k < numDofs(); ++k) f[k] += out[k];
  }
}

const std::vector<double>* Model::termOutput(const std::string& name) const {
  const auto it = termOutputs_.find(name);
  return it == termOutputs_.end() ? nullptr : &it->second;
}

double Model::termEnergy() const {
  double e = 0.0;
  for (const std::unique_ptr<ForceTerm>& term : forceTerms_) e += term->storedEnergy();
  return e;
}

std::vector<std::string> Model::termHistoryNames() const {
  std::vector<std::string> names;
  for (const std::unique_ptr<ForceTerm>& term : forceTerms_) {
    const std::vector<std::string> own = term->historyNames();
    names.insert(names.end(), own.begin(), own.end());
  }
  return names;
}

std::vector<double> Model::termHistoryShares() const {
  std::vector<double> shares;
  for (const std::unique_ptr<ForceTerm>& term : forceTerms_) {
    const std::vector<double> own = term->historyShares();
    shares.insert(shares.end(), own.begin(), own.end());
  }
  return shares;
}

std::string Model::termWorkSummary() const {
  std::string all;
  for (const std::unique_ptr<ForceTerm>& term : forceTerms_) all += (all.empty() ? "" : "; ") + term->workSummary();
  return all;
}

}  // namespace pf
