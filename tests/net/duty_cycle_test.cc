#include "net/duty_cycle.h"

#include <gtest/gtest.h>

namespace sanet::net {
namespace {

TEST(DutyCycle, AwakeFromEachWindowsStartForAwakeSecondsThenAsleepToThePeriodsEnd) {
  const DutyCycle cycle{10, 2, 1};  // awake [1, 3), [11, 13), ...
  EXPECT_TRUE(CycleAt(cycle, 0).asleep);
  EXPECT_DOUBLE_EQ(CycleAt(cycle, 0).next_change, 1);
  EXPECT_FALSE(CycleAt(cycle, 1).asleep) << "a window starts awake";
  EXPECT_DOUBLE_EQ(CycleAt(cycle, 1).next_change, 3);
  EXPECT_FALSE(CycleAt(cycle, 2.999).asleep);
  EXPECT_TRUE(CycleAt(cycle, 3).asleep) << "and ends asleep";
  EXPECT_DOUBLE_EQ(CycleAt(cycle, 3).next_change, 11);
  EXPECT_FALSE(CycleAt(cycle, 1001.5).asleep);
  EXPECT_DOUBLE_EQ(CycleAt(cycle, 1001.5).next_change, 1003);
}

TEST(DutyCycle, AwakeThroughTheWholePeriodNeverSleeps) {
  const DutyCycle cycle{5, 5, 0};
  for (double t : {0.0, 2.5, 4.999, 5.0, 123.4}) EXPECT_FALSE(CycleAt(cycle, t).asleep) << t;
  EXPECT_DOUBLE_EQ(CycleAt(cycle, 7).next_change, 10);
}

}  // namespace
}  // namespace sanet::net
