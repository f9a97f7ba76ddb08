// A controller drives a robot 20 m to a way point behind a wall, seeing the wall only with its
// own range sensors, and stops there.
#include <gtest/gtest.h>

#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

struct Outcome {
  Pose2D end;
  double closest_to_wall = 1e9;   // m, from the robot's centre to the wall's surface
  double farthest_from_line = 0;  // m, the detour
  bool arrived = false;
};

Outcome DriveAroundWall(ModelKind kind) {
  sim::RunSpec spec =
      Spec(120, {Robot("r", kind, {0, 0, 0},
                       UseController("waypoint", {{"waypoints", Table({{20, 0}})}, {"speed", Scalar(0.5)}}))});
  spec.obstacles = {Wall({10, -4}, {10, 4})};
  sim::World world(spec, BuiltinRegistry());
  Outcome o;
  world.Observe([&](const sim::WorldSnapshot&) {
    const Pose2D p = world.model(0).body().pose();
    o.closest_to_wall = std::min(o.closest_to_wall, DistanceToBox(p.position(), spec.obstacles[0].box));
    o.farthest_from_line = std::max(o.farthest_from_line, std::fabs(p.y));
  });
  world.Run({});
  o.end = world.model(0).body().pose();
  return o;
}

TEST(Navigation, Omni3GoesAroundTheWallAndStopsAtTheWayPoint) {
  const Outcome o = DriveAroundWall(ModelKind::kOmni3);
  EXPECT_LT(Norm(o.end.position() - Vec2{20, 0}), 0.5);
  EXPECT_GT(o.farthest_from_line, 4.0) << "to pass the wall it must go beyond its end";
  EXPECT_GT(o.closest_to_wall, 0.19) << "the body (radius 0.19 m) never overlaps the wall";
}

TEST(Navigation, DiffDriveWithItsLaserGoesAroundTheWallToo) {
  const Outcome o = DriveAroundWall(ModelKind::kDiffDrive);
  EXPECT_LT(Norm(o.end.position() - Vec2{20, 0}), 0.5);
  EXPECT_GT(o.farthest_from_line, 4.0);
  EXPECT_GT(o.closest_to_wall, 0.2);
}

}  // namespace
}  // namespace sanet
