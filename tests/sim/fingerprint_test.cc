// The fingerprint of the README scenario is pinned: a change to physics, sensors, controllers,
// scheduling or output formats that alters any result changes it, and must then be committed
// with a new value and a message that says why.
#include <gtest/gtest.h>

#include "scenario/scenario_loader.h"
#include "support/test_world.h"

namespace sanet {
namespace {

TEST(Fingerprint, ReadmeScenarioMatchesTheCommittedValue) {
  const scenario::Scenario sc = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/around-the-wall.yaml");
  sim::World world(sc.run, testing::BuiltinRegistry());
  // Issue 28: the scenario's motes moved off the robot's way (it used to shove two of them).
  EXPECT_EQ(world.Run({}).fingerprint, "3dff464fa2648c1f");
}

}  // namespace
}  // namespace sanet
