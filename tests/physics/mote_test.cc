// Motes rest without cost until something pushes them, then move like 50 g boxes.
#include <gtest/gtest.h>

#include "physics/physics_world.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

TEST(Mote, UntouchedMotesAreNotIntegrated) {
  auto world = physics::CreateOdeWorld({});
  for (int i = 0; i < 25; ++i) world->add_mote({}, {i * 2.0, 0, 0});
  for (int i = 0; i < 100; ++i) world->step(0.005);
  EXPECT_EQ(world->awake_body_count(), 0u);
}

TEST(Mote, AWorldOfMotesNeedsNoPhysicsSteps) {
  sim::World world(Spec(10, {Robot("a", ModelKind::kMote, {0, 0, 0}), Robot("b", ModelKind::kMote, {1, 0, 0})}),
                   BuiltinRegistry());
  EXPECT_EQ(world.Run({}).physics_steps, 0u);
}

TEST(Mote, ARobotPushesAMoteAndTheMoteComesToRestAgain) {
  sim::RunSpec spec = Spec(12, {Robot("r", ModelKind::kOmni3, {0, 0, 0},
                                      UseController("constant_velocity", {{"vx", Scalar(0.4)}, {"stop", Scalar(5)}})),
                                Robot("m", ModelKind::kMote, {1.0, 0, 0})});
  sim::World world(spec, BuiltinRegistry());
  world.Run({});
  const Pose2D mote = world.model(1).body().pose();
  EXPECT_GT(mote.x, 1.3) << "the robot drove into the mote, which should have been pushed";
  EXPECT_FALSE(world.model(1).body().awake()) << "seven seconds after the push it should rest";
  EXPECT_NEAR(world.model(1).body().position3().z, 0.05, 0.01) << "still on the ground";
}

}  // namespace
}  // namespace sanet
