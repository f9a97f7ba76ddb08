#include "robots/sensors.h"

#include <algorithm>
#include <cmath>

namespace sanet::robots {

RangeSensorSpec RangeSensorSpec::Ring(int count, double radius, double height, double max_range) {
  RangeSensorSpec s;
  for (int i = 0; i < count; ++i) s.angles.push_back(2 * kPi * i / count);
  s.mount_radius = radius;
  s.mount_height = height;
  s.max_range = max_range;
  return s;
}

RangeSensorSpec RangeSensorSpec::Fan(double fov, int beams, double mount_x, double height, double max_range) {
  RangeSensorSpec s;
  // Ordered right to left, as laser scanners report.
  for (int i = 0; i < beams; ++i) s.angles.push_back(beams == 1 ? 0 : -fov / 2 + fov * i / (beams - 1));
  s.mount_x = mount_x;
  s.mount_height = height;
  s.max_range = max_range;
  return s;
}

RangeScan RangeSensor::Read(const physics::PhysicsWorld& world, const physics::Body& self) {
  const Pose2D pose = self.pose();
  RangeScan scan;
  scan.angles = spec_.angles;
  scan.max_range = spec_.max_range;
  const Vec2 mount = ToWorld(pose, {spec_.mount_x, 0});
  std::vector<physics::PhysicsWorld::Ray> rays;
  rays.reserve(spec_.angles.size());
  for (double angle : spec_.angles) {
    const double heading = pose.theta + angle;
    const Vec2 dir{std::cos(heading), std::sin(heading)};
    const Vec2 origin = mount + dir * spec_.mount_radius;
    rays.push_back({{origin.x, origin.y, spec_.mount_height}, {dir.x, dir.y, 0}});
  }
  scan.ranges = world.cast_rays(rays, spec_.max_range, &self);
  if (spec_.noise > 0)
    for (double& range : scan.ranges) range = std::clamp(rng_.Gaussian(range, spec_.noise), 0.0, spec_.max_range);
  return scan;
}

void Odometry::Update(const physics::Vehicle& vehicle) {
  const std::size_t n = vehicle.wheel_count();
  std::vector<double> delta(n);
  if (last_angles_.size() != n) last_angles_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = vehicle.wheel_angle(i);
    delta[i] = a - last_angles_[i];
    last_angles_[i] = a;
  }
  Twist2D d = kinematics_.BodyTwist(delta);  // a displacement, since the rates are increments
  if (noise_ > 0) {
    d.vx *= 1 + rng_.Gaussian(0, noise_);
    d.vy *= 1 + rng_.Gaussian(0, noise_);
    d.omega *= 1 + rng_.Gaussian(0, noise_);
  }
  const Vec2 step = Rotate({d.vx, d.vy}, pose_.theta + d.omega / 2);
  pose_.x += step.x;
  pose_.y += step.y;
  pose_.theta = WrapAngle(pose_.theta + d.omega);
}

std::optional<BearingReading> BearingSensor::Read(const Pose2D& self, const Pose2D& target) {
  const Vec2 offset = target.position() - self.position();
  const double distance = Norm(offset);
  if (distance > spec_.range) return std::nullopt;
  BearingReading r{distance, WrapAngle(std::atan2(offset.y, offset.x) - self.theta)};
  if (spec_.noise_distance > 0) r.distance = std::max(0.0, rng_.Gaussian(r.distance, spec_.noise_distance));
  if (spec_.noise_angle > 0) r.bearing = WrapAngle(rng_.Gaussian(r.bearing, spec_.noise_angle));
  return r;
}

Pose2D GroundTruthSensor::Read(const Pose2D& truth) {
  if (noise_position_ <= 0 && noise_angle_ <= 0) return truth;
  return {rng_.Gaussian(truth.x, noise_position_), rng_.Gaussian(truth.y, noise_position_),
          WrapAngle(rng_.Gaussian(truth.theta, noise_angle_))};
}

}  // namespace sanet::robots
