#include "Solver.hpp"

namespace pf {

const std::vector<double>& SolverResume::vector(const std::string& name) const {
  auto it = vectors.find(name);
  if (it == vectors.end()) throw std::logic_error("resume point without the vector '" + name + "'");
  return it->second;
}

double SolverResume::scalar(const std::string& name) const {
  auto it = scalars.find(name);
  if (it == scalars.end()) throw std::logic_error("resume point without the scalar '" + name + "'");
  return it->second;
}

}  // namespace pf
