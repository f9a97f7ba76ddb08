// An agent's control steps on the shared clock's grid: the latest due step runs once, slept-through
// steps are counted as missed, never run in a burst.
#include "usarsim_agent/agent_steps.h"

#include <gtest/gtest.h>

namespace sanet::usarsim_agent {
namespace {

TEST(StepGrid, RunsEachStepOnceAtItsGridTime) {
  StepGrid grid(10);
  EXPECT_EQ(grid.Due(0.0), 0.0);
  EXPECT_FALSE(grid.Due(0.05)) << "not due yet";
  EXPECT_EQ(grid.Due(0.1003), 0.1) << "a late wake-up runs the step at its grid time";
  EXPECT_FALSE(grid.Due(0.1004)) << "never twice";
  EXPECT_EQ(grid.Due(0.2), 0.2);
  EXPECT_EQ(grid.run(), 3u);
  EXPECT_EQ(grid.missed(), 0u);
}

TEST(StepGrid, CountsStepsSleptThroughAndRunsOnlyTheLatest) {
  StepGrid grid(10);
  grid.Due(0.0);
  EXPECT_EQ(grid.Due(0.35), 0.3) << "0.1 and 0.2 were slept through";
  EXPECT_EQ(grid.missed(), 2u);
  EXPECT_EQ(grid.run(), 2u);
  EXPECT_EQ(grid.Due(0.41), 0.4);
  EXPECT_NEAR(grid.lateness().max, 0.05, 1e-12);
}

TEST(StepGrid, StepsBeforeTheFirstAreNotMissed) {
  StepGrid grid(10);
  EXPECT_EQ(grid.Due(12.34), 12.3) << "an agent that connects at 12.34 s starts with step 123";
  EXPECT_EQ(grid.missed(), 0u);
  for (int k = 124; k <= 223; ++k) EXPECT_EQ(grid.Due(k / 10.0 + 0.001), k / 10.0);
  EXPECT_NEAR(grid.achieved_rate(), 10, 1e-9);
}

}  // namespace
}  // namespace sanet::usarsim_agent
