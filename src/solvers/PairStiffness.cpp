#include "PairStiffness.hpp"

#include <algorithm>
#include <limits>

#include "model/Model.hpp"

namespace pf {

double defaultPreconditionerRadius(const Model& model) {
  double threeD = 0.0;
  for (const BlockModel& b : model.blocks())
    if (!isPlanar(b.material->dimension())) threeD = 1.0;
  return model.max(threeD) > 0.0 ? 2.0 : 3.0;
}

namespace {

// Which bonds the matrix keeps, and one global stiffening factor (boost) so that the kept bonds carry the
// second moment sum(k r^2) of all bonds: the smooth modes, which the Krylov solve needs the preconditioner
// for, see the same stiffness. Collective (one reduction).
std::vector<char> keptBonds(const Model& model, const std::vector<double>& c, double radiusFactor, double& boost) {
  const DistributedLayout& L = model.layout();
  const BondFamily& fam = L.family();
  const std::vector<double>& V = model.volume();
  std::vector<char> keep(fam.neighbors.size(), 1);
  double moment[2] = {0, 0}, total[2];
  for (int i = 0; i < model.numOwned(); ++i) {
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
  return keep;
}

}  // namespace

double pairStiffnessRows(
    const Model& model, double radiusFactor, const std::vector<double>* shift,
    const std::function<void(const std::vector<long long>& rows, const std::vector<std::size_t>& counts)>& sized,
    const std::function<void(std::size_t r, const long long* columns, const double* values, std::size_t n)>& row) {
  const DistributedLayout& L = model.layout();
  const BondFamily& fam = L.family();
  const std::vector<int>& gid = L.gids();
  const std::vector<double>& x = model.coordinates();
  const std::vector<double>& V = model.volume();
  const std::vector<double>& m = model.weightedVolume();
  const std::vector<char>& fixed = model.prescribedMask();
  const std::vector<double> c = model.pairStiffness();
  const int owned = model.numOwned();
  double boost = 1.0;
  const std::vector<char> keep = keptBonds(model, c, radiusFactor, boost);
  // Free row (i, a): its diagonal block first, then each kept bond's coupling (the pass that counts and the
  // pass that emits compute the same entries in the same order).
  std::vector<long long> cols;
  std::vector<double> vals;
  auto freeRow = [&](int i, int a) {
    cols.clear();
    vals.clear();
    for (int d = 0; d < 3; ++d) {
      cols.push_back(3LL * gid[i] + d);
      vals.push_back(0.0);
    }
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
      if (!keep[b]) continue;
      const int j = fam.neighbors[b];
      double n[3];
      for (int d = 0; d < 3; ++d) n[d] = (x[3 * j + d] - x[3 * i + d]) / fam.refLength[b];
      const double k = boost * c[b] * (1.0 + m[i] / m[j]) * V[j];
      for (int d = 0; d < 3; ++d) {
        if (n[a] * n[d] == 0.0) continue;  // planar bonds: no z coupling; storing zeros doubled the work
        vals[d] += k * n[a] * n[d];
        cols.push_back(3LL * gid[j] + d);
        vals.push_back(-k * n[a] * n[d]);
      }
    }
    if (shift) vals[a] += (*shift)[3 * i + a];
  };
  std::vector<long long> rowIds;
  std::vector<std::size_t> counts;
  double diagTotal = 0;
  long long diagCount = 0;
  for (int i = 0; i < owned; ++i)
    for (int a = 0; a < 3; ++a) {
      rowIds.push_back(3LL * gid[i] + a);
      if (fixed[3 * i + a]) {  // s alone on the diagonal, once s is known
        counts.push_back(1);
        continue;
      }
      freeRow(i, a);
      counts.push_back(cols.size());
      diagTotal += vals[a];
      ++diagCount;
    }
  double in[2] = {diagTotal, static_cast<double>(diagCount)}, out[2];
  L.comm().sum(in, out, 2);
  const double scale = out[1] > 0 ? out[0] / out[1] : 1.0;
  sized(rowIds, counts);
  std::size_t r = 0;
  for (int i = 0; i < owned; ++i)
    for (int a = 0; a < 3; ++a, ++r) {
      if (fixed[3 * i + a]) {  // the constraint x = xbar decouples a prescribed row
        row(r, &rowIds[r], &scale, 1);
        continue;
      }
      freeRow(i, a);
      row(r, cols.data(), vals.data(), cols.size());
    }
  return scale;
}

}  // namespace pf
