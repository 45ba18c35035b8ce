#include <gtest/gtest.h>

#include "core/StateStore.hpp"

TEST(StateStore, CommitAndRollbackOnlyTouchHistoryFields) {
  pf::StateStore s;
  s.allocate({{"A", pf::Location::Node, true, false}, {"B", pf::Location::Bond, false, false}}, 2, 3);
  s.trial("A")[0] = 1.0;
  s.commit();
  s.trial("A")[0] = 2.0;
  EXPECT_EQ(s.committed("A")[0], 1.0);
  s.rollback();
  EXPECT_EQ(s.trial("A")[0], 1.0);
  EXPECT_THROW(s.trial("missing"), std::logic_error);
}
