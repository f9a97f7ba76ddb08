#include "ros2_agent/readings.h"

#include <algorithm>
#include <cmath>

namespace sanet::ros2_agent {
namespace {

double Clamped(float range, float max) {
  return std::isfinite(range) && range <= max ? std::max(0.0f, range) : static_cast<double>(max);
}

}  // namespace

double Seconds(const msg::builtin_interfaces::Time& t) { return t.sec + t.nanosec * 1e-9; }

msg::builtin_interfaces::Time StampAt(double seconds) {
  msg::builtin_interfaces::Time t;
  const double whole = std::floor(seconds);
  t.sec = static_cast<std::int32_t>(whole);
  t.nanosec = static_cast<std::uint32_t>(std::min(999999999.0, std::round((seconds - whole) * 1e9)));
  return t;
}

Pose2D PoseOf(const msg::geometry_msgs::Pose& pose) {
  const auto& q = pose.orientation;
  return {pose.position.x, pose.position.y, std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))};
}

Pose2D InWorld(const Pose2D& start, const Pose2D& relative) {
  const double c = std::cos(start.theta), s = std::sin(start.theta);
  return {start.x + c * relative.x - s * relative.y, start.y + s * relative.x + c * relative.y,
          std::remainder(start.theta + relative.theta, 2 * M_PI)};
}

RangeScan ScanOf(const msg::sensor_msgs::LaserScan& scan) {
  RangeScan out;
  out.max_range = scan.range_max;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    out.angles.push_back(scan.angle_min + static_cast<double>(i) * scan.angle_increment);
    out.ranges.push_back(Clamped(scan.ranges[i], scan.range_max));
  }
  return out;
}

double RangeOf(const msg::sensor_msgs::Range& range) { return Clamped(range.range, range.max_range); }

msg::geometry_msgs::Twist TwistOf(const Twist2D& v) {
  msg::geometry_msgs::Twist t;
  t.linear.x = v.vx;
  t.linear.y = v.vy;
  t.angular.z = v.omega;
  return t;
}

}  // namespace sanet::ros2_agent
