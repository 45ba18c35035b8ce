#pragma once
// What the model builder knows of a block (its group's material, horizon, damage and field operators), and the
// rules between blocks it checks before building: each throws an InputError naming the deck and the block group.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/BondFilter.hpp"
#include "core/Expression.hpp"
#include "core/FieldOperator.hpp"
#include "core/Material.hpp"
#include "discretization/Discretization.hpp"
#include "input/Deck.hpp"

namespace pf {

struct BlockSpec {
  std::string name, materialName;
  double horizon = 0.0;                                 // 0 for an expression (known per point only)
  std::shared_ptr<const Material> material;
  std::vector<std::shared_ptr<const FieldOperator>> fieldOperators;
  double criticalStretch = 0.0;  // 0: no damage model
  bool ndoBand = false;
  double tensileStrength = 0.0;  // Maximum Principal Stress damage; 0: not that model
  std::shared_ptr<const Expression> stretchOfTime;      // Time Dependent Critical Stretch
  double bulkModulus = 0.0;                             // K of the material; 0: it has no moduli (Diffusion)
  std::shared_ptr<const BondFilters> initialBreaks;     // Initial Damage
  std::shared_ptr<const Expression> horizonExpression;  // Horizon in x, y, z; null: the constant horizon
  std::string group;                                    // its Blocks sub-list, for messages
};

// Interface Aware damage only as Critical Stretch's rule: every block on an Interface Aware model of one value.
void requireUniformInterfaceAware(const Deck& deck);

// Every block's horizon reaches past the grid spacing.
void requireHorizonsReachNeighbours(const Deck& deck, const PointCloud& cloud);

// One body takes one layout of per-point rows; the gather forms that need it share one constant horizon.
void requireEqualHorizonsForGatherForms(const std::map<int, BlockSpec>& blocks, const std::string& inputFile);

}  // namespace pf
