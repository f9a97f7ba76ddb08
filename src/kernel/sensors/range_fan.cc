#include "sensors/range_fan.h"

#include <algorithm>
#include <cmath>

namespace sanet::sensors {

RangeFan RangeFan::Ring(int count, double radius, double height, double max_range) {
  RangeFan s;
  for (int i = 0; i < count; ++i) s.angles.push_back(2 * kPi * i / count);
  s.mount_radius = radius;
  s.mount_height = height;
  s.max_range = max_range;
  return s;
}

RangeFan RangeFan::Fan(double fov, int beams, double mount_x, double height, double max_range) {
  RangeFan s;
  for (int i = 0; i < beams; ++i) s.angles.push_back(beams == 1 ? 0 : -fov / 2 + fov * i / (beams - 1));
  s.mount_x = mount_x;
  s.mount_height = height;
  s.max_range = max_range;
  return s;
}

std::optional<SensorReading> RangeFanSensor::Read(const ReadContext& /*context*/) {
  const physics::Body& self = mount_.model.body();
  const Pose2D pose = self.pose();
  RangeScan scan;
  scan.angles = fan_.angles;
  if (fan_.direction != 0)
    for (double& angle : scan.angles) angle += fan_.direction;
  scan.max_range = fan_.max_range;
  const Vec2 mount = ToWorld(pose, {fan_.mount_x, 0});
  std::vector<physics::PhysicsWorld::Ray> rays;
  rays.reserve(fan_.angles.size());
  for (double angle : scan.angles) {
    const double heading = pose.theta + angle;
    const Vec2 dir{std::cos(heading), std::sin(heading)};
    const Vec2 origin = mount + dir * fan_.mount_radius;
    rays.push_back({{origin.x, origin.y, fan_.mount_height}, {dir.x, dir.y, 0}});
  }
  scan.ranges = mount_.world.cast_rays(rays, fan_.max_range, &self);
  if (fan_.noise > 0)
    for (double& range : scan.ranges)
      range = std::clamp(mount_.random.Gaussian(range, fan_.noise), 0.0, fan_.max_range);
  return scan;
}

}  // namespace sanet::sensors
