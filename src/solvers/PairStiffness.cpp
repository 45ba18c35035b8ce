#include "PairStiffness.hpp"

#include <algorithm>
#include <limits>

#include "model/Model.hpp"

namespace pf {

PairRows pairStiffnessRows(const Model& model, double radiusFactor, const std::vector<double>* shift) {
  const DistributedLayout& L = model.layout();
  const BondFamily& fam = L.family();
  const std::vector<int>& gid = L.gids();
  const std::vector<double>& x = model.coordinates();
  const std::vector<double>& V = model.volume();
  const std::vector<double>& m = model.weightedVolume();
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double> c = model.pairStiffness();
  const int owned = model.numOwned();
  // Which bonds the matrix keeps, and one global stiffening factor so that the kept bonds carry the second
  // moment sum(k r^2) of all bonds: the smooth modes, which the Krylov solve needs the preconditioner for,
  // see the same stiffness.
  std::vector<char> keep(fam.neighbors.size(), 1);
  double boost = 1.0;
  {
    double moment[2] = {0, 0}, total[2];
    for (int i = 0; i < owned; ++i) {
      double shortest = std::numeric_limits<double>::max();
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) shortest = std::min(shortest, fam.refLength[b]);
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
        const double r = fam.refLength[b], kr2 = c[b] * V[fam.neighbors[b]] * r * r;
        keep[b] = r <= radiusFactor * shortest * (1 + 1e-9);
        moment[0] += kr2;
        if (keep[b]) moment[1] += kr2;
      }
    }
    L.comm().sum(moment, total, 2);
    boost = total[1] > 0 ? total[0] / total[1] : 1.0;
  }
  PairRows rows;
  rows.offsets.push_back(0);
  double diagTotal = 0;
  long long diagCount = 0;
  std::vector<std::size_t> diagAt(3 * owned, 0);  // where each free row's diagonal entry sits
  for (int i = 0; i < owned; ++i) {
    for (int a = 0; a < 3; ++a) {
      const long long row = 3LL * gid[i] + a;
      rows.row.push_back(row);
      if (fixed[3 * i + a]) {  // filled with s below, once s is known
        rows.columns.push_back(row);
        rows.values.push_back(0.0);
        diagAt[3 * i + a] = rows.values.size() - 1;
        rows.offsets.push_back(rows.columns.size());
        continue;
      }
      const std::size_t first = rows.columns.size();
      for (int d = 0; d < 3; ++d) {
        rows.columns.push_back(3LL * gid[i] + d);
        rows.values.push_back(0.0);
      }
      for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
        if (!keep[b]) continue;
        const int j = fam.neighbors[b];
        double n[3];
        for (int d = 0; d < 3; ++d) n[d] = (x[3 * j + d] - x[3 * i + d]) / fam.refLength[b];
        const double k = boost * c[b] * (1.0 + m[i] / m[j]) * V[j];
        for (int d = 0; d < 3; ++d) {
          if (n[a] * n[d] == 0.0) continue;  // planar bonds: no z coupling; storing zeros doubled the work
          rows.values[first + d] += k * n[a] * n[d];
          rows.columns.push_back(3LL * gid[j] + d);
          rows.values.push_back(-k * n[a] * n[d]);
        }
      }
      if (shift) rows.values[first + a] += (*shift)[3 * i + a];
      diagTotal += rows.values[first + a];
      ++diagCount;
      rows.offsets.push_back(rows.columns.size());
    }
  }
  double in[2] = {diagTotal, static_cast<double>(diagCount)}, out[2];
  L.comm().sum(in, out, 2);
  rows.scale = out[1] > 0 ? out[0] / out[1] : 1.0;
  // Prescribed rows: s on the diagonal alone (the constraint x = xbar decouples them).
  for (int k = 0; k < 3 * owned; ++k)
    if (fixed[k]) rows.values[diagAt[k]] = rows.scale;
  return rows;
}

}  // namespace pf
