// StageTimings: stages in order, one entry per name, sums across runs.
#include <segmat/common/stage_timings.h>

#include <gtest/gtest.h>

using namespace segmat;

TEST(StageTimings, KeepsPipelineOrderAndOneEntryPerStage)
{
  StageTimings t;
  EXPECT_TRUE(t.empty());
  t.add("mat", 0.5);
  t.add("graph", 0.25);
  t.add("mat", 0.125); // same stage again: summed, order kept
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "mat");
  EXPECT_DOUBLE_EQ(t[0].seconds, 0.625);
  EXPECT_EQ(t[1].name, "graph");
  EXPECT_DOUBLE_EQ(t.seconds("graph"), 0.25);
  EXPECT_DOUBLE_EQ(t.seconds("transfer"), 0.0);
  EXPECT_FALSE(t.contains("transfer"));
  EXPECT_DOUBLE_EQ(t.total(), 0.875);
}

TEST(StageTimings, SumsTheRunsOfARepeatedPipeline)
{
  StageTimings run1, run2, all;
  run1.add("medial", 1.0);
  run1.add("transfer", 0.5);
  run2.add("medial", 2.0);
  run2.add("labels", 0.25);
  all.add(run1);
  all.add(run2);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[2].name, "labels");
  EXPECT_DOUBLE_EQ(all.seconds("medial"), 3.0);
  EXPECT_DOUBLE_EQ(all.total(), 3.75);
  all.clear();
  EXPECT_TRUE(all.empty());
}

TEST(StageTimings, ScopedTimerAddsItsScopeToOneStage)
{
  StageTimings t;
  {
    ScopedStageTimer timer(t, "grow");
  }
  {
    ScopedStageTimer timer(t, "grow");
  }
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].name, "grow");
  EXPECT_GE(t[0].seconds, 0.0);
}
