// The drive-limit rule every mode applies (robots::LimitDrive): simulated nodes, agents, ROS 2 robots.
#include <gtest/gtest.h>

#include <cmath>

#include "robots/node_model.h"

namespace sanet::robots {
namespace {

TEST(LimitDrive, ADifferentialDriveNeitherSlidesNorExceedsItsLimits) {
  const ModelSpec diff = ModelSpec::Defaults(ModelKind::kDiffDrive);
  const Twist2D v = LimitDrive(diff, {5.0, 0.7, -9.0});
  EXPECT_DOUBLE_EQ(v.vy, 0.0);
  EXPECT_DOUBLE_EQ(v.vx, diff.max_speed);
  EXPECT_DOUBLE_EQ(v.omega, -diff.max_turn_rate);
  const Twist2D back = LimitDrive(diff, {-5.0, 0, 0.5});
  EXPECT_DOUBLE_EQ(back.vx, -diff.max_speed);
  EXPECT_DOUBLE_EQ(back.omega, 0.5);
}

TEST(LimitDrive, AnOmniRobotKeepsItsDirectionAtItsTopSpeed) {
  const ModelSpec omni = ModelSpec::Defaults(ModelKind::kOmni3);
  const Twist2D v = LimitDrive(omni, {3.0, 4.0, 10.0});
  EXPECT_NEAR(std::hypot(v.vx, v.vy), omni.max_speed, 1e-12);
  EXPECT_NEAR(v.vy / v.vx, 4.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(v.omega, omni.max_turn_rate);
}

TEST(LimitDrive, ACommandWithinTheLimitsIsUntouched) {
  const ModelSpec omni = ModelSpec::Defaults(ModelKind::kOmni3);
  const Twist2D v = LimitDrive(omni, {0.1, -0.2, 0.3});
  EXPECT_DOUBLE_EQ(v.vx, 0.1);
  EXPECT_DOUBLE_EQ(v.vy, -0.2);
  EXPECT_DOUBLE_EQ(v.omega, 0.3);
}

}  // namespace
}  // namespace sanet::robots
