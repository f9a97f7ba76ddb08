// The driver, front ends' one seam with a running world: a robot has one owner at a time and is
// refused to every other front end with a sentence naming the owner; only the owner reads the
// sensors, once, and everyone else sees what it read; driving goes through the node's checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sensors/ground_truth/ground_truth.h"
#include "sensors/odometry/odometry.h"
#include "sim/world.h"
#include "support/test_world.h"

namespace sanet {
namespace {

sim::RunSpec TwoRobots() {
  sim::RunSpec spec = testing::Spec(1, {testing::Robot("r1", robots::ModelKind::kDiffDrive, {0, 0, 0}),
                                        testing::Robot("r2", robots::ModelKind::kOmni3, {3, 0, 0})});
  testing::SensorSettings<sensors::OdometrySettings>(spec.nodes[0], "odometry").noise = 0.05;
  testing::SensorSettings<sensors::GroundTruthSettings>(spec.nodes[0], "ground_truth").noise_position =
      0.1;  // noisy: a second read would draw again
  return spec;
}

TEST(Driver, ARobotOwnedByOneFrontEndIsRefusedToAnother) {
  sim::World world(TwoRobots(), testing::BuiltinRegistry());
  sim::Driver& driver = world.driver();
  const NodeId r1 = *driver.Lookup("r1");
  EXPECT_FALSE(driver.Claim(r1, "robot server client 127.0.0.1:4000"));
  EXPECT_FALSE(driver.Claim(r1, "robot server client 127.0.0.1:4000")) << "its owner may claim it again";
  const auto refused = driver.Claim(r1, "ROS 2 face");
  ASSERT_TRUE(refused);
  EXPECT_EQ(*refused, "robot 'r1' is already driven by robot server client 127.0.0.1:4000");
  EXPECT_EQ(driver.OwnerOf(r1), "robot server client 127.0.0.1:4000");
  EXPECT_FALSE(driver.Claim(*driver.Lookup("r2"), "ROS 2 face")) << "another robot is free";
  driver.Release(r1, "ROS 2 face");  // not its to release
  EXPECT_TRUE(driver.Claim(r1, "ROS 2 face"));
  driver.Release(r1, "robot server client 127.0.0.1:4000");
  EXPECT_FALSE(driver.Claim(r1, "ROS 2 face"));
}

TEST(Driver, OnlyTheOwnerReadsTheSensorsAndOthersSeeItsReading) {
  sim::World world(TwoRobots(), testing::BuiltinRegistry());
  sim::Driver& driver = world.driver();
  const NodeId r1 = *driver.Lookup("r1");
  EXPECT_EQ(driver.LastReadings(r1).time, -1) << "nothing read yet";
  EXPECT_THROW(driver.TakeReadings(r1, "viewer"), std::logic_error);
  ASSERT_FALSE(driver.Claim(r1, "owner"));
  const sim::SensorReadings taken = driver.TakeReadings(r1, "owner");
  ASSERT_TRUE(taken.odometry());
  const sim::SensorReadings& seen = driver.LastReadings(r1);
  EXPECT_EQ(seen.time, taken.time);
  EXPECT_EQ(seen.odometry()->x, taken.odometry()->x);
  EXPECT_EQ(seen.ground_truth.x, taken.ground_truth.x);
  EXPECT_NE(taken.ground_truth.x, 0) << "the noisy ground truth drew";
  EXPECT_EQ(driver.TakeReadings(r1, "owner").ground_truth.x, taken.ground_truth.x)
      << "a second read at the same instant draws nothing";
  world.Start({});
  world.RunUntil(0.5);
  EXPECT_NE(driver.TakeReadings(r1, "owner").ground_truth.x, taken.ground_truth.x) << "a later read draws again";
  world.Finish();
}

TEST(Driver, OnlyTheOwnerDrivesAndScenarioControllersAreNotClaimed) {
  sim::RunSpec spec = TwoRobots();
  spec.nodes[1].controller = testing::UseController("constant_velocity", {{"vx", testing::Scalar(0.1)}});
  sim::World world(spec, testing::BuiltinRegistry());
  sim::Driver& driver = world.driver();
  EXPECT_THROW(driver.NodeOf(0, "nobody"), std::logic_error);
  const auto refused = driver.Claim(1, "ROS 2 face");
  ASSERT_TRUE(refused);
  EXPECT_EQ(*refused, "'r2' is driven by its scenario controller (constant_velocity)");
  try {
    driver.Claim(999, "ROS 2 face");
    ADD_FAILURE() << "an id the run does not have is a front end's bug";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "no node 999: the run has 2");
  }
}

TEST(Driver, AStopEndsTheRunBetweenPiecesAndSaysWhy) {
  sim::World world(TwoRobots(), testing::BuiltinRegistry());
  world.Start({});
  EXPECT_TRUE(world.RunUntil(0.3));
  world.driver().Stop("the script had seen enough");
  EXPECT_FALSE(world.RunUntil(0.6)) << "the run is over";
  world.Finish();
  EXPECT_EQ(world.ended_by(), "the script had seen enough");
  EXPECT_NEAR(world.ended_at(), 0.3, 1e-6);
}

TEST(Driver, FinishingBeforeTheDurationSaysSo) {
  sim::World world(TwoRobots(), testing::BuiltinRegistry());
  world.Start({});
  EXPECT_TRUE(world.RunUntil(0.2));
  world.Finish();
  EXPECT_EQ(world.ended_by(), "finished early by whoever stepped it (World::Finish)");
}

TEST(Driver, DrivingGoesThroughTheNodesChecks) {
  sim::World world(TwoRobots(), testing::BuiltinRegistry());
  ASSERT_FALSE(world.driver().Claim(0, "test"));
  Node& node = world.driver().NodeOf(0, "test");
  EXPECT_FALSE(node.Drive({std::numeric_limits<double>::quiet_NaN(), 0, 0}));
  EXPECT_FALSE(node.SetWheelSpeeds({std::numeric_limits<double>::infinity(), 0}));
  EXPECT_TRUE(node.Drive({0.2, 0, 0}));
}

}  // namespace
}  // namespace sanet
