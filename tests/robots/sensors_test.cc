// Range sensors measure the distance to walls and boxes, on either physics engine.
#include <gtest/gtest.h>

#include "sensors/bearing/bearing.h"
#include "sensors/range_fan.h"
#include "sensors/sonar/sonar.h"
#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

constexpr double kTolerance = 0.02;  // m, without noise

// Settles the robots on the ground, then returns the world for reading.
void Settle(sim::World& world) { world.Run({}); }

class RangeSensors : public ::testing::TestWithParam<physics::Engine> {};

TEST_P(RangeSensors, IrReadsTheDistanceToAWallAndABox) {
  sim::RunSpec spec = On(GetParam(), Spec(0.2, {Robot("r", ModelKind::kOmni3, {0, 0, 0})}));
  spec.obstacles = {Wall({0.6, -2}, {0.6, 2}),       // face at x = 0.5, ahead
                    Box({0.3, 0.9}, 0.4, 0.4, 0.5),  // lower face at y = 0.7, ahead left
                    Box({-0.7, 0}, 0.2, 0.2, 0.5)};  // face at x = -0.6, behind
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  const RangeScan ir = *world.parts().node(0).Ir();
  ASSERT_EQ(ir.ranges.size(), 6u);
  const double r = world.spec().nodes[0].model.omni3.body_radius;  // rays start at the body's edge
  EXPECT_NEAR(ir.angles[0], 0, 1e-9);
  EXPECT_NEAR(ir.ranges[0], 0.5 - r, kTolerance);
  EXPECT_NEAR(ir.ranges[3], 0.6 - r, kTolerance);
  // The 60-degree beam meets the box's lower face (y = 0.7) at x = 0.40, inside the box's extent.
  const double d60 = 0.7 / std::sin(kPi / 3) - r;
  EXPECT_NEAR(ir.ranges[1], d60, kTolerance);
  EXPECT_DOUBLE_EQ(ir.ranges[4], ir.max_range) << "nothing at 240 degrees";
}

TEST_P(RangeSensors, LaserReadsTheDistanceToAWallAheadAndABoxToTheSide) {
  sim::RunSpec spec = On(GetParam(), Spec(0.2, {Robot("r", ModelKind::kDiffDrive, {0, 0, 0})}));
  spec.obstacles = {Wall({3.0, -1}, {3.0, 1}),   // face at x = 2.9
                    Box({0.2, -2.0}, 1, 1, 1)};  // face at y = -1.5, right
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  const RangeScan scan = *world.parts().node(0).Laser();
  ASSERT_EQ(scan.ranges.size(), 181u);
  const double mount_x = 0.18;
  EXPECT_NEAR(scan.angles[90], 0, 1e-9);
  EXPECT_NEAR(scan.ranges[90], 2.9 - mount_x, kTolerance);
  EXPECT_NEAR(scan.angles[0], -kPi / 2, 1e-9) << "beams go right to left";
  EXPECT_NEAR(scan.ranges[0], 1.5, kTolerance);
  EXPECT_DOUBLE_EQ(scan.ranges[180], scan.max_range) << "nothing to the left";
  // A beam 10 degrees to the right meets the wall's face at 2.72 / cos 10.
  EXPECT_NEAR(scan.angles[80], -kPi / 18, 1e-9);
  EXPECT_NEAR(scan.ranges[80], (2.9 - mount_x) / std::cos(kPi / 18), kTolerance);
}

// The sonar (the worked example of docs/architecture.md): the nearest thing within its cone.
TEST_P(RangeSensors, SonarReadsTheNearestThingInItsCone) {
  sim::RunSpec spec = On(GetParam(), Spec(0.2, {Robot("r", ModelKind::kOmni3, {0, 0, 0})}));
  robots::ModelSpec& model = spec.nodes[0].model;
  model.sensors["sonar"] = {"sonar", sensors::FindKind("sonar")->DefaultSettings(model)};
  sensors::SonarSettings left = std::any_cast<sensors::SonarSettings>(model.sensors["sonar"].settings);
  left.direction = kPi / 2;
  model.sensors["sonar_left"] = {"sonar", left};
  spec.obstacles = {Wall({2.1, -3}, {2.1, 3}),         // face at x = 2.0, ahead
                    Box({1.6, 0.35}, 0.2, 0.2, 0.5)};  // a post ahead left, 10 to 17 degrees off the axis
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  const double r = model.omni3.body_radius;
  const auto ahead = world.parts().node(0).SensorAs<RangeScan>("sonar");
  ASSERT_TRUE(ahead);
  ASSERT_EQ(ahead->ranges.size(), 1u);
  EXPECT_EQ(ahead->angles, std::vector<double>{0});
  // The post's near face (x = 1.5) is within the 0.5 rad cone: nearer than the wall.
  EXPECT_LT(ahead->ranges[0], 1.6 - r);
  EXPECT_GT(ahead->ranges[0], 1.5 - r - kTolerance);
  const auto side = world.parts().node(0).SensorAs<RangeScan>("sonar_left");
  ASSERT_TRUE(side);
  EXPECT_DOUBLE_EQ(side->ranges[0], side->max_range) << "nothing to the left within 4 m";
  EXPECT_NEAR(side->angles[0], kPi / 2, 1e-12);
}

// A laser turned by `direction` looks backwards; its angles are in the robot frame.
TEST_P(RangeSensors, ATurnedLaserLooksWhereItPoints) {
  sim::RunSpec spec = On(GetParam(), Spec(0.2, {Robot("r", ModelKind::kDiffDrive, {0, 0, 0})}));
  robots::ModelSpec& model = spec.nodes[0].model;
  sensors::RangeFan rear = sensors::RangeFan::Fan(1.0, 11, -0.25, 0.2, 8);
  rear.direction = kPi;
  model.sensors["laser_rear"] = {"laser", rear};
  spec.obstacles = {Wall({-2.1, -3}, {-2.1, 3})};  // face at x = -2.0, behind
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  const auto scan = world.parts().node(0).SensorAs<RangeScan>("laser_rear");
  ASSERT_TRUE(scan);
  EXPECT_NEAR(scan->angles[5], kPi, 1e-12) << "the middle beam points backwards";
  EXPECT_NEAR(scan->ranges[5], 2.0 - 0.25, kTolerance) << "from the mount at the rear";
  EXPECT_DOUBLE_EQ(world.parts().node(0).Laser()->ranges[90], 8) << "nothing ahead";
}

INSTANTIATE_TEST_SUITE_P(BothEngines, RangeSensors, kEngines, EngineName);

TEST(Laser, NoiseChangesReadingsAroundTheTruth) {
  sim::RunSpec spec = Spec(0.2, {Robot("r", ModelKind::kDiffDrive, {0, 0, 0})});
  SensorSettings<sensors::RangeFan>(spec.nodes[0], "laser").noise = 0.05;
  spec.obstacles = {Wall({3.0, -5}, {3.0, 5})};
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  const RangeScan a = *world.parts().node(0).Laser();
  const RangeScan b = *world.parts().node(0).Laser();
  EXPECT_NE(a.ranges[90], b.ranges[90]);
  double mean = 0;
  for (int i = 80; i <= 100; ++i) mean += a.ranges[i] * std::cos(a.angles[i]);
  EXPECT_NEAR(mean / 21, 2.72, 0.04);
}

TEST(Bearing, AnswersOnlyWithinRange) {
  sim::RunSpec spec =
      Spec(0.1, {Robot("r", ModelKind::kOmni3, {0, 0, kPi / 2}), Robot("near", ModelKind::kMote, {3, 3, 0}),
                 Robot("far", ModelKind::kMote, {30, 0, 0})});
  spec.nodes[0].model.sensors["bearing"] = {"bearing", sensors::BearingSettings{10, 0, 0}};
  sim::World world(spec, BuiltinRegistry());
  Settle(world);
  auto near = world.parts().node(0).Bearing(1);
  ASSERT_TRUE(near);
  EXPECT_NEAR(near->distance, std::sqrt(18.0), 0.02);
  EXPECT_NEAR(near->bearing, -kPi / 4, 0.01) << "north-east seen from a robot facing north is to its right";
  EXPECT_FALSE(world.parts().node(0).Bearing(2));
}

}  // namespace
}  // namespace sanet
