#include "NodeSets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/InputError.hpp"
#include "core/Log.hpp"
#include "core/Words.hpp"

namespace pf {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& msg) {
  throw InputError(file + ": " + path + ": " + msg);
}

// Printed by rank 0 only (every rank resolves the same node sets).
void warn(const std::string& file, const std::string& path, const std::string& msg) {
  pf::warn(file + ": " + path + ": " + msg);  // qualified: this 3-argument warn hides core's
}

// Ids are 1-based global ids in the order of the cloud (Peridigm's convention); every id of the cloud
// is returned, held here or not (resolveNodeSets keeps the held ones).
std::vector<int> idsToIndices(const std::vector<std::string>& words, long long n, const std::string& file,
                              const std::string& path, const std::string& where, int& skipped) {
  std::vector<int> out;
  out.reserve(words.size());
  for (const std::string& w : words) {
    long id = 0;
    try {
      std::size_t used = 0;
      id = std::stol(w, &used);
      if (used != w.size()) throw std::invalid_argument(w);
    } catch (const std::exception&) {
      fail(file, path, where + "'" + w + "' is not a node id");
    }
    // Peridigm skips node-set ids its mesh does not have (several of its own decks list id 0, a relic of
    // 0-based ids), so such ids are dropped here too, loudly: the condition applies to the other ids only.
    if (id < 1 || id > n) {
      warn(file, path, where + "node id " + w + " does not exist (the discretization has ids 1.." +
                           std::to_string(n) + "); ignored, as Peridigm does");
      ++skipped;
      continue;
    }
    out.push_back(static_cast<int>(id - 1));
  }
  return out;
}

std::vector<int> region(const NodeSetSpec& r, const PointCloud& c, const CloudReductions& reduce) {
  std::vector<int> out;
  const int n = c.size();
  if (!r.face.empty()) {
    const std::string& f = r.face;
    const int a = f.back() - 'X';
    const bool low = f.compare(0, 3, "Min") == 0;
    double ext = low ? std::numeric_limits<double>::max() : std::numeric_limits<double>::lowest();
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    for (int i = 0; i < n; ++i) {
      const double v = c.x[3 * i + a];
      ext = low ? std::min(ext, v) : std::max(ext, v);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    ext = low ? -reduce.max(-ext) : reduce.max(ext);
    lo = -reduce.max(-lo);
    hi = reduce.max(hi);
    // Default: half a grid spacing catches one row of a lattice and nothing else.
    double tol = r.tolerance;
    if (tol <= 0.0) tol = c.spacing > 0.0 ? 0.5 * c.spacing : 1e-9 * std::max(1.0, hi - lo);
    for (int i = 0; i < n; ++i)
      if (std::fabs(c.x[3 * i + a] - ext) <= tol) out.push_back(c.gid[i]);
    return out;
  }
  const std::array<double, 3>& lo = r.lo;
  const std::array<double, 3>& hi = r.hi;
  double scale = 0.0;
  for (int i = 0; i < 3 * n; ++i) scale = std::max(scale, std::fabs(c.x[i]));
  scale = reduce.max(scale);
  const double slack = 1e-12 * std::max(1.0, scale);  // bounds are inclusive; round-off must not exclude a row
  for (int i = 0; i < n; ++i) {
    bool in = true;
    for (int a = 0; a < 3 && in; ++a) {
      const double v = c.x[3 * i + a];
      in = v >= lo[a] - slack && v <= hi[a] + slack;
    }
    if (in) out.push_back(c.gid[i]);
  }
  return out;
}

}  // namespace

std::map<std::string, std::vector<int>> resolveNodeSets(const std::vector<NodeSetSpec>& nodeSets,
                                                        const PointCloud& cloud, const std::string& inputFile,
                                                        const CloudReductions& reduce) {
  std::map<std::string, std::vector<int>> sets = cloud.generatedNodeSets;
  sets["All"] = cloud.gid;
  // The listed ids this rank holds (cloud.gid is ascending).
  auto held = [&](std::vector<int> ids) {
    ids.erase(std::remove_if(ids.begin(), ids.end(),
                             [&](int g) { return !std::binary_search(cloud.gid.begin(), cloud.gid.end(), g); }),
              ids.end());
    return ids;
  };

  for (const NodeSetSpec& spec : nodeSets) {
    const std::string& name = spec.name;
    const std::string path = "Boundary Conditions/" + name;
    std::vector<int> ids;
    int skipped = 0;  // ids outside the discretization, dropped with a warning
    if (spec.kind == NodeSetSpec::Kind::Region) {
      ids = region(spec, cloud, reduce);
    } else if (spec.kind == NodeSetSpec::Kind::Ids) {
      ids = held(idsToIndices(splitWords(spec.text), cloud.numGlobal, inputFile, path, "", skipped));
    } else {
      forEachDataLine(spec.text, inputFile, path, "node set", [&](const std::string& line, const std::string& where) {
        const std::vector<int> more =
            held(idsToIndices(splitWords(line), cloud.numGlobal, inputFile, path, where + ": ", skipped));
        ids.insert(ids.end(), more.begin(), more.end());
      });
    }
    // A set the deck defines replaces a built-in or generated one of the same name (the input layer has
    // warned): Peridigm has no built-in sets, so a Peridigm deck's "All" is its own.
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    // A set emptied by dropped ids is kept (Peridigm's conditions on it then act on no node); one that lists
    // nothing at all is still an error.
    const bool empty = reduce.sum(static_cast<double>(ids.size())) == 0;
    if (empty && skipped == 0) fail(inputFile, path, "node set '" + name + "' is empty");
    if (empty) warn(inputFile, path, "node set '" + name + "' holds no node of the discretization");
    sets[name] = std::move(ids);
  }
  for (const auto& [name, ids] : cloud.generatedNodeSets)
    if (reduce.sum(static_cast<double>(ids.size())) == 0)
      fail(inputFile, "Discretization", "node set '" + name + "' of the discretization holds no point");
  return sets;
}

}  // namespace pf
