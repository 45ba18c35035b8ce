#include "ComputeClasses.hpp"

#include <algorithm>
#include <limits>

#include "parallel/Communicator.hpp"

namespace pf {

void ComputeClasses::add(const ComputeSpec& spec, std::vector<int> points, bool vector) {
  // Nearest_Point_Data reads one point, which only its owner holds: a sum over the ranks delivers it.
  const ComputeSpec::Calculation calc =
      spec.kind == ComputeSpec::Kind::NearestPointData ? ComputeSpec::Calculation::Sum : spec.calculation;
  computes_.push_back({spec, std::move(points), vector, calc});
}

std::vector<std::string> ComputeClasses::names() const {
  std::vector<std::string> out;
  for (const Compute& c : computes_) {
    if (!c.vector) out.push_back(c.spec.label);
    else
      for (const char* x : {"X", "Y", "Z"}) out.push_back(c.spec.label + x);
  }
  return out;
}

std::vector<double> ComputeClasses::evaluate(const Communicator& comm,
                                             const std::function<double(const std::string&, int, int)>& value) const {
  // Sums in one reduction; minima and maxima in one max-reduction (a minimum as the maximum of the negatives).
  std::vector<double> sums, extremes;
  std::vector<int> where;  // per output value: its index into sums (>= 0) or extremes (-1 - index)
  const double lowest = std::numeric_limits<double>::lowest();
  for (const Compute& c : computes_) {
    for (int k = 0; k < (c.vector ? 3 : 1); ++k) {
      if (c.calculation == ComputeSpec::Calculation::Sum) {
        double s = 0.0;  // a point on one rank: only its owner adds
        for (int i : c.points) s += value(c.spec.variable, k, i);
        where.push_back(static_cast<int>(sums.size()));
        sums.push_back(s);
      } else {
        const double sign = c.calculation == ComputeSpec::Calculation::Maximum ? 1.0 : -1.0;
        double m = lowest;
        for (int i : c.points) m = std::max(m, sign * value(c.spec.variable, k, i));
        where.push_back(-1 - static_cast<int>(extremes.size()));
        extremes.push_back(m);
      }
    }
  }
  std::vector<double> sumAll(sums.size()), extAll(extremes.size());
  if (!sums.empty()) comm.sum(sums.data(), sumAll.data(), static_cast<int>(sums.size()));
  if (!extremes.empty()) comm.max(extremes.data(), extAll.data(), static_cast<int>(extremes.size()));
  std::vector<double> out;
  std::size_t n = 0;
  for (const Compute& c : computes_) {
    const double sign = c.calculation == ComputeSpec::Calculation::Minimum ? -1.0 : 1.0;
    for (int k = 0; k < (c.vector ? 3 : 1); ++k, ++n)
      out.push_back(where[n] >= 0 ? sumAll[where[n]] : sign * extAll[-1 - where[n]]);
  }
  return out;
}

}  // namespace pf
