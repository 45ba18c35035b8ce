#include "SolvedStates.hpp"

#include "LoadStepping.hpp"
#include "model/Model.hpp"

namespace pf {

void SolvedStates::record(const std::vector<double>& state) {
  if (count >= 3) {
    u[0].swap(u[1]);
    u[1].swap(u[2]);
    count = 2;
  }
  u[static_cast<int>(count)] = state;
  count += 1;
}

bool predictQuadratic(const Model& model, const SolvedStates& states, std::vector<double>& u) {
  if (states.count < 3) return false;
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double>&a = states.u[0], &b = states.u[1], &c = states.u[2];
  // Load coordinate s along d = the next load's prescribed values minus the newest state's: s_c = 0, next = 1.
  double in[5] = {0, 0, 0, 0, 0}, out[5];
  for (std::size_t k = 0; k < u.size(); ++k)
    if (fixed[k]) {
      const double d = u[k] - c[k], da = a[k] - c[k], db = b[k] - c[k];
      in[0] += d * d;
      in[1] += da * d;
      in[2] += db * d;
      in[3] += da * da;
      in[4] += db * db;
    }
  model.layout().comm().sum(in, out, 5);
  if (!(out[0] > 0.0)) return false;
  const double sa = out[1] / out[0], sb = out[2] / out[0];
  // One direction (a before b before c before the next load), the states spanning at least a quarter of the step
  // (the weights grow with the cube of the reach), and on the line of d to round-off (proportional loading).
  if (!(sa < sb && sb < 0.0 && sa <= -0.25)) return false;
  const double offLine = 1e-12;
  if (out[3] - sa * sa * out[0] > offLine * out[3] || out[4] - sb * sb * out[0] > offLine * out[4]) return false;
  // Lagrange's weights at s = 1 through (sa, sb, 0).
  const double wa = (1.0 - sb) / ((sa - sb) * sa);
  const double wb = (1.0 - sa) / ((sb - sa) * sb);
  const double wc = (1.0 - sa) * (1.0 - sb) / (sa * sb);
  for (std::size_t k = 0; k < u.size(); ++k)
    if (!fixed[k]) u[k] = wa * a[k] + wb * b[k] + wc * c[k];
  return true;
}

void SolvedStates::carriedBy(CarriedState& own) {
  own.vectors.push_back({"Solved State 1", &u[0]});
  own.vectors.push_back({"Solved State 2", &u[1]});
  own.vectors.push_back({"Solved State 3", &u[2]});
  own.scalars.push_back({"Solved States", &count});
}

}  // namespace pf
