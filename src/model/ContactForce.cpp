#include "ContactForce.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "discretization/NeighborSearch.hpp"

namespace pf {

ContactForce::ContactForce(const DistributedLayout& layout, std::vector<double> volume, std::vector<int> block,
                           ContactSetup setup)
    : layout_(layout), volume_(std::move(volume)), block_(std::move(block)),
      setup_(std::move(setup)), ghosts_(layout) {
  for (int b : block_) horizon_.push_back(setup_.horizonOf.at(b));
  for (const auto& kv : setup_.horizonOf) lawTableSide_ = std::max<std::size_t>(lawTableSide_, kv.first + 1);
  lawTable_.assign(lawTableSide_ * lawTableSide_, -1);
  for (const auto& [pair, law] : setup_.lawOf)
    lawTable_[pair.first * lawTableSide_ + pair.second] = lawTable_[pair.second * lawTableSide_ + pair.first] = law;
}

// The law table is dense over block ids (a deck's ids are small): this is asked for every candidate of a search.
int ContactForce::lawBetween(int blockA, int blockB) const {
  const int n = static_cast<int>(lawTableSide_);
  if (blockA < 0 || blockB < 0 || blockA >= n || blockB >= n) return -1;
  return lawTable_[static_cast<std::size_t>(blockA) * lawTableSide_ + blockB];
}

void ContactForce::search(const std::vector<double>& y) {
  const int numOwned = layout_.numOwned();
  // The owned points of blocks that interact with some block: the only ones that send, search and are found.
  std::vector<char> active(numOwned, 0);
  std::map<int, bool> interacts;
  for (const auto& kv : setup_.lawOf) interacts[kv.first.first] = interacts[kv.first.second] = true;
  PointCloud mine;
  mine.numGlobal = layout_.numGlobal();
  std::vector<int> activeOwned;
  for (int i = 0; i < numOwned; ++i) {
    if (!interacts.count(block_[i])) continue;
    active[i] = 1;
    activeOwned.push_back(i);
    mine.gid.push_back(layout_.gids()[i]);
    mine.x.insert(mine.x.end(), y.begin() + 3 * i, y.begin() + 3 * i + 3);
    mine.volume.push_back(volume_[i]);
    mine.block.push_back(block_[i]);
  }
  ghosts_.rebuild(mine, setup_.searchRadius * (1.0 + 1e-9));
  const PointCloud& g = ghosts_.ghosts();
  // Candidates within the search radius: the active owned points first (the queries), then the ghosts.
  std::vector<double> pts = mine.x;
  pts.insert(pts.end(), g.x.begin(), g.x.end());
  const int numActive = static_cast<int>(activeOwned.size());
  BondFamily near;
  buildFamilies(pts, numActive, std::vector<double>(numActive, setup_.searchRadius), near);
  const BondFamily& fam = layout_.family();
  offsets_.assign(numOwned + 1, 0);
  partners_.clear();
  partnerLaw_.clear();
  std::vector<std::pair<int, int>> row;  // (gid, contact-point index) of one point's partners
  for (int a = 0, i = 0; i < numOwned; ++i) {
    offsets_[i] = static_cast<int>(partners_.size());
    if (!active[i]) continue;
    row.clear();
    for (int k = near.offsets[a]; k < near.offsets[a + 1]; ++k) {
      const int c = near.neighbors[k];
      const bool owned = c < numActive;
      if (lawBetween(block_[i], owned ? mine.block[c] : g.block[c - numActive]) < 0) continue;
      row.push_back({owned ? mine.gid[c] : g.gid[c - numActive], owned ? activeOwned[c] : numOwned + (c - numActive)});
    }
    ++a;
    if (row.empty()) continue;
    // Its own bond family is no partner (Peridigm's rule): only the few candidates left are looked up in it.
    auto bonded = [&](int gid) {
      for (int k = fam.offsets[i]; k < fam.offsets[i + 1]; ++k)
        if (layout_.gids()[fam.neighbors[k]] == gid) return true;
      return false;
    };
    row.erase(std::remove_if(row.begin(), row.end(), [&](const std::pair<int, int>& r) { return bonded(r.first); }),
              row.end());
    std::sort(row.begin(), row.end());
    for (const auto& [gid, c] : row) {
      partners_.push_back(c);
      partnerLaw_.push_back(lawBetween(block_[i], c < numOwned ? block_[c] : g.block[c - numOwned]));
    }
  }
  offsets_[numOwned] = static_cast<int>(partners_.size());
  ghostHorizon_.clear();
  for (int b : g.block) ghostHorizon_.push_back(setup_.horizonOf.at(b));
  searched_ = true;
  ++searches_;
}

void ContactForce::force(long step, double t, const double* y, const double* v, double* f) {
  const int numOwned = layout_.numOwned();
  // Peridigm searches at the start and before every Search Frequency-th step moves the points, at the positions
  // the previous step ended with; a resumed run searches at its first step's.
  if (!searched_ || step % setup_.searchFrequency == 0)
    search(searched_ && step > 0 ? yPrevious_ : std::vector<double>(y, y + 3 * static_cast<std::size_t>(numOwned)));
  yPrevious_.assign(y, y + 3 * static_cast<std::size_t>(numOwned));
  ownedYV_.resize(6 * static_cast<std::size_t>(numOwned));
  for (int i = 0; i < numOwned; ++i)
    for (int c = 0; c < 3; ++c) ownedYV_[6 * i + c] = y[3 * i + c], ownedYV_[6 * i + 3 + c] = v[3 * i + c];
  const PointCloud& g = ghosts_.ghosts();
  ghostYV_.resize(6 * g.gid.size());
  ghosts_.update(ownedYV_.data(), ghostYV_.data(), 6);
  mu_.resize(setup_.laws.size());
  for (std::size_t l = 0; l < mu_.size(); ++l) mu_[l] = setup_.laws[l].frictionAt(t);
  std::fill(f, f + 3 * static_cast<std::size_t>(numOwned), 0.0);
  for (int i = 0; i < numOwned; ++i)
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k)
      contacts_ += addShortRangeForce(setup_.laws[partnerLaw_[k]].law, mu_[partnerLaw_[k]], pairOf(i, k), &f[3 * i]);
  evaluations_ += static_cast<double>(partners_.size());
}

std::string ContactForce::workSummary() const {
  const double local[4] = {searches_, static_cast<double>(partners_.size()), evaluations_, contacts_};
  double all[4];
  layout_.comm().sum(local, all, 4);
  char line[200];
  std::snprintf(line, sizeof line, "contact: %.0f searches, %.0f partner pairs at the last, %.0f pair evaluations, %.0f in contact",
                local[0], all[1], all[2], all[3]);
  return line;
}

ContactPair ContactForce::pairOf(int i, int k) const {
  const int numOwned = layout_.numOwned();
  const int c = partners_[k];
  const bool owned = c < numOwned;
  const double* yv = owned ? &ownedYV_[6 * c] : &ghostYV_[6 * (c - numOwned)];
  return ContactPair{&ownedYV_[6 * i], yv, &ownedYV_[6 * i + 3], yv + 3,
                     owned ? volume_[c] : ghosts_.ghosts().volume[c - numOwned], horizon_[i],
                     owned ? horizon_[c] : ghostHorizon_[c - numOwned]};
}

int ContactForce::partnerBlock(int k) const {
  const int numOwned = layout_.numOwned(), c = partners_[k];
  return c < numOwned ? block_[c] : ghosts_.ghosts().block[c - numOwned];
}

double ContactForce::storedEnergy() const {
  double e = 0.0;
  if (ownedYV_.empty()) return e;  // no force() yet
  for (int i = 0; i < layout_.numOwned(); ++i)
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k)
      e += shortRangeHalfEnergy(setup_.laws[partnerLaw_[k]].law, pairOf(i, k), volume_[i]);
  return e;
}

std::vector<std::string> ContactForce::historyNames() const {
  std::vector<std::string> names;
  for (const auto& [pair, law] : setup_.lawOf)
    if (pair.first != pair.second)
      for (const char* c : {"X", "Y", "Z"})
        names.push_back("Contact_Force_On_block_" + std::to_string(pair.first) + "_From_block_" +
                        std::to_string(pair.second) + "_" + c);
  return names;
}

// The force on block a from block b (a < b) is the sum over a's owned points of V_i times the density its
// partners in b give; b's from a is its opposite (the law conserves momentum), so it is not written.
std::vector<double> ContactForce::historyShares() const {
  std::map<std::pair<int, int>, std::size_t> column;
  for (const auto& [pair, law] : setup_.lawOf)
    if (pair.first != pair.second) column.emplace(pair, 3 * column.size());
  std::vector<double> share(3 * column.size(), 0.0);
  if (ownedYV_.empty()) return share;
  for (int i = 0; i < layout_.numOwned(); ++i)
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const auto it = column.find({block_[i], partnerBlock(k)});
      if (it == column.end()) continue;  // the same block, or i in the pair's larger block
      double fi[3] = {0.0, 0.0, 0.0};
      addShortRangeForce(setup_.laws[partnerLaw_[k]].law, mu_[partnerLaw_[k]], pairOf(i, k), fi);
      for (int c = 0; c < 3; ++c) share[it->second + c] += volume_[i] * fi[c];
    }
  return share;
}

}  // namespace pf
