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

// StateSpec::initial: every entry, trial and committed, starts at it (e.g. 1 on a tensor's diagonal).
TEST(StateStore, FieldsStartAtTheirInitialValue) {
  pf::StateStore s;
  s.allocate({{"F", pf::Location::Node, true, false, 1.0}, {"G", pf::Location::Node, false, false, -2.0}}, 3, 0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(s.trial("F")[i], 1.0);
    EXPECT_EQ(s.committed("F")[i], 1.0);
    EXPECT_EQ(s.trial("G")[i], -2.0);
  }
  s.rollback();
  EXPECT_EQ(s.trial("F")[2], 1.0);
}
