// The drives move as commanded, on either physics engine: omni3 forward, sideways and turning
// in place; diffdrive circles; walls stop them.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

struct Track {
  Pose2D start, end;
  double turned = 0;  // unwrapped heading change, rad
  std::vector<Pose2D> poses;
};

class Drive : public ::testing::TestWithParam<physics::Engine> {};

sim::NodeSpec Driven(ModelKind kind, Twist2D v, Pose2D pose = {0, 0, 0}) {
  return Robot(
      "r", kind, pose,
      UseController("constant_velocity", {{"vx", Scalar(v.vx)}, {"vy", Scalar(v.vy)}, {"omega", Scalar(v.omega)}}));
}

Track DriveFor(ModelKind kind, Twist2D v, double seconds) {
  sim::World world(On(Drive::GetParam(), Spec(seconds, {Driven(kind, v)})), BuiltinRegistry());
  Track t;
  t.start = world.model(0).body().pose();
  double last_theta = t.start.theta;
  world.Observe([&](const sim::WorldSnapshot&) {
    const Pose2D p = world.model(0).body().pose();
    t.turned += WrapAngle(p.theta - last_theta);
    last_theta = p.theta;
    t.poses.push_back(p);
  });
  world.Run({});
  t.end = world.model(0).body().pose();
  return t;
}

TEST_P(Drive, Omni3ForwardAtThirtyCentimetresPerSecondForTenSecondsCoversThreeMetres) {
  const Track t = DriveFor(ModelKind::kOmni3, {0.3, 0, 0}, 10);
  EXPECT_NEAR(t.end.x - t.start.x, 3.0, 0.3);
  EXPECT_NEAR(t.end.y, 0.0, 0.15);
  EXPECT_NEAR(t.end.theta, 0.0, 5 * kPi / 180);
}

TEST_P(Drive, Omni3SidewaysKeepsItsHeading) {
  const Track t = DriveFor(ModelKind::kOmni3, {0, 0.3, 0}, 10);
  EXPECT_NEAR(t.end.y, 3.0, 0.3);
  EXPECT_NEAR(t.end.x, 0.0, 0.15);
  for (const Pose2D& p : t.poses) ASSERT_LT(std::fabs(p.theta), 5 * kPi / 180) << "heading drifted";
}

TEST_P(Drive, Omni3TurnsInPlace) {
  const Track t = DriveFor(ModelKind::kOmni3, {0, 0, 1.0}, 10);
  EXPECT_NEAR(t.turned, 10.0, 1.0);  // rad
  for (const Pose2D& p : t.poses) ASSERT_LT(Norm(p.position()), 0.05) << "centre wandered";
}

TEST_P(Drive, Omni3OdometryFollowsTheTruePose) {
  sim::World world(On(GetParam(), Spec(8, {Driven(ModelKind::kOmni3, {0.3, 0.1, 0.2}, {1, 2, 0.5})})),
                   BuiltinRegistry());
  world.Run({});
  const Pose2D truth = world.model(0).body().pose();
  const Pose2D odo = *world.parts().node(0).Odometry();
  EXPECT_GT(Norm(truth.position() - Vec2{1, 2}), 1.5);
  EXPECT_LT(Norm(truth.position() - odo.position()), 0.1);
  EXPECT_LT(std::fabs(WrapAngle(truth.theta - odo.theta)), 0.05);
}

TEST_P(Drive, DiffDriveConstantSpeedAndTurnRateDriveACircleOfRadiusVOverOmega) {
  const double v = 0.5, omega = 0.25;  // radius 2 m, one lap in 25 s
  const Track t = DriveFor(ModelKind::kDiffDrive, {v, 0, omega}, 32);
  // Fit the circle on the last full lap (after the start-up transient).
  const std::size_t lap = static_cast<std::size_t>(2 * kPi / omega / 0.005);
  ASSERT_GT(t.poses.size(), lap);
  Vec2 centre{0, 0};
  for (std::size_t i = t.poses.size() - lap; i < t.poses.size(); ++i) centre = centre + t.poses[i].position();
  centre = centre * (1.0 / lap);
  double radius = 0;
  for (std::size_t i = t.poses.size() - lap; i < t.poses.size(); ++i) radius += Norm(t.poses[i].position() - centre);
  radius /= lap;
  EXPECT_NEAR(radius, v / omega, 0.1 * v / omega);
  EXPECT_GT(t.turned, 6.0);  // it went round, counter-clockwise
}

TEST_P(Drive, DiffDriveEqualWheelSpeedsDriveStraightAtWheelRadiusTimesSpeed) {
  ParamValue wheels;
  wheels.shape = ParamValue::Shape::kList;
  wheels.rows = {{"4", "4"}};  // rad/s; 4 * 0.0975 m = 0.39 m/s
  sim::World world(On(GetParam(), Spec(5, {Robot("r", ModelKind::kDiffDrive, {0, 0, 0},
                                                 UseController("constant_velocity", {{"wheel_speeds", wheels}}))})),
                   BuiltinRegistry());
  world.Run({});
  const Pose2D p = world.model(0).body().pose();
  EXPECT_NEAR(p.x, 0.39 * 5, 0.1 * 0.39 * 5);
  EXPECT_NEAR(p.y, 0, 0.05);
}

TEST_P(Drive, DiffDriveStandsStillWithoutCommands) {
  sim::World world(On(GetParam(), Spec(5, {Robot("r", ModelKind::kDiffDrive, {3, 4, 1})})), BuiltinRegistry());
  world.Run({});
  EXPECT_LT(Norm(world.model(0).body().pose().position() - Vec2{3, 4}), 0.01);
}

// Driving at a wall 1 m ahead for long enough to cross it twice over: the robot stops at the
// wall's face (within 2 cm of touching it) and stays there.
TEST_P(Drive, AWallStopsEitherRobot) {
  for (ModelKind kind : {ModelKind::kOmni3, ModelKind::kDiffDrive}) {
    sim::RunSpec spec = On(GetParam(), Spec(8, {Driven(kind, {0.3, 0, 0})}));
    spec.obstacles = {Wall({1.6, -3}, {1.6, 3})};  // face at x = 1.5
    sim::World world(spec, BuiltinRegistry());
    double farthest = 0;
    world.Observe([&](const sim::WorldSnapshot&) { farthest = std::max(farthest, world.model(0).body().pose().x); });
    world.Run({});
    const robots::ModelSpec& m = spec.nodes[0].model;
    const double front =
        kind == ModelKind::kOmni3 ? m.omni3.body_radius : m.diffdrive.body_length / 2 - m.diffdrive.caster_offset / 4;
    EXPECT_NEAR(world.model(0).body().pose().x, 1.5 - front, 0.02) << "stopped at the face";
    EXPECT_LT(farthest, 1.5 - front + 0.02) << "never went into the wall";
  }
}

INSTANTIATE_TEST_SUITE_P(BothEngines, Drive, kEngines, EngineName);

}  // namespace
}  // namespace sanet
