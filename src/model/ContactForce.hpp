#pragma once
// Peridigm's contact (the deck's "Contact" list, input/Deck.hpp ContactSpec) as a force term (core/ForceTerm.hpp):
// every Search Frequency steps each owned point of an interacting block looks for partners within the Search
// Radius in the deformed configuration, on any rank (parallel/MovingGhosts), leaving out its own bond family (broken
// bonds included, as Peridigm); every step the short-range law (core/ShortRangeContact.hpp) acts on the partners
// closer than the Contact Radius. A point's force is summed on its owner over its partners in gid order, so it
// does not depend on the partition. Fragments of one block contact each other through a Self interaction.
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "core/Expression.hpp"
#include "core/ForceTerm.hpp"
#include "core/ShortRangeContact.hpp"
#include "parallel/DistributedLayout.hpp"
#include "parallel/MovingGhosts.hpp"

namespace pf {

// A contact law and its friction coefficient, constant or a function of t.
struct ContactLaw {
  ShortRangeForceLaw law;
  double friction = 0.0;
  std::shared_ptr<const Expression> frictionOfTime;  // null: the constant
  double frictionAt(double t) const { return frictionOfTime ? (*frictionOfTime)(0.0, 0.0, 0.0, t) : friction; }
};

struct ContactSetup {
  double searchRadius = 0.0;
  int searchFrequency = 1;
  std::vector<ContactLaw> laws;
  std::map<std::pair<int, int>, int> lawOf;  // (block id, block id), smaller first -> index into laws
  std::map<int, double> horizonOf;           // every block id of the cloud -> its horizon
};

class ContactForce : public ForceTerm {
 public:
  // volume: the layout's overlap points' volumes; block: the owned points' block ids.
  ContactForce(const DistributedLayout& layout, std::vector<double> volume, std::vector<int> block, ContactSetup setup);
  std::string outputName() const override { return "Contact_Force_Density"; }
  void force(long step, double t, const double* y, const double* v, double* f) override;
  double storedEnergy() const override;
  // Contact_Force_On_block_<a>_From_block_<b>_X, _Y, _Z (N) for each pair a < b of interacting blocks.
  std::vector<std::string> historyNames() const override;
  std::vector<double> historyShares() const override;
  // "contact: S searches, P partner pairs at the last, E pair evaluations, C in contact" (over all ranks).
  std::string workSummary() const override;
  // Partners found at the last search, over this rank's owned points (for the benchmark's counts).
  std::size_t numPartners() const { return partners_.size(); }

 private:
  void search(const std::vector<double>& y);  // collective: ghosts and partners at positions y (owned)
  int lawBetween(int blockA, int blockB) const;
  // Owned point i and its k-th partner (partners_ index) as the law sees them, at the last force()'s state.
  ContactPair pairOf(int i, int k) const;
  int partnerBlock(int k) const;
  const DistributedLayout& layout_;
  std::vector<double> volume_;  // per overlap point
  std::vector<int> block_;          // per owned point
  ContactSetup setup_;
  MovingGhosts ghosts_;
  std::size_t lawTableSide_ = 0;
  std::vector<int> lawTable_;  // law of blocks (a, b) at a * side + b, -1 for none
  bool searched_ = false;
  double searches_ = 0, evaluations_ = 0, contacts_ = 0;  // work counts on this rank (doubles: summed by the comm)
  std::vector<double> yPrevious_;  // owned positions at the last evaluation: the next search's, as Peridigm's
  // Per owned point (offsets: numOwned + 1): its partners as contact-point indices (< numOwned: an owned point,
  // else numOwned + a ghost), in gid order, and the law of each pair.
  std::vector<int> offsets_, partners_, partnerLaw_;
  std::vector<double> ownedYV_, ghostYV_;  // y and v, 6 per point
  std::vector<double> mu_;                   // per law: its friction coefficient at the last force()'s time
  std::vector<double> horizon_, ghostHorizon_;  // per owned point, per ghost: its block's horizon
};

}  // namespace pf
